package pod.e2e

import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.parse
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.doubles.shouldBeGreaterThanOrEqual
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import pod.cli.Pod
import pod.cli.json.Event
import pod.core.vehicle.LandedState
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.seconds

class ActionCliSpec : StringSpec({

    "pod arm, mode, takeoff, goto and land fly a simulated copter, each ending with a done line" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 51, timeScale = 5.0, gcs = "udpout://127.0.0.1:$port"))
            try {
                sim.start(this)
                // The command's last line, its done event (every line before it must decode too).
                suspend fun pod(vararg args: String): Event.Done {
                    val out = Captured()
                    withContext(Dispatchers.IO) { Pod(out).parse(args.toList() + listOf("--connect", "udpin:127.0.0.1:$port", "--sysid", "51", "--json")) }
                    return out.events.last().shouldBeInstanceOf<Event.Done>().also { it.sysid shouldBe 51 }
                }
                // At 5x a parked copter's 10 s auto-disarm would beat the 1 Hz heartbeat that confirms arming.
                pod("param", "set", "DISARM_DELAY", "0").run { listOf(action, name, value) } shouldBe listOf("param-set", "DISARM_DELAY", 0.0)
                pod("param", "get", "WPNAV_SPEED").run { listOf(action, name, value) } shouldBe listOf("param-get", "WPNAV_SPEED", 500.0)
                pod("mode", "guided").mode shouldBe "GUIDED"
                pod("arm").armed shouldBe true
                val takeoff = pod("takeoff", "12")
                takeoff.action shouldBe "takeoff"
                takeoff.relativeAltM!! shouldBeGreaterThanOrEqual 11.0
                (sim.state.value.relativeAltitude.meters >= 11.0) shouldBe true
                val home = SimVehicleConfig.DEFAULT_HOME
                val north = home.offset(north = pod.core.units.Distance(20.0), east = pod.core.units.Distance(0.0))
                pod("goto", "${north.latitude}", "${north.longitude}", "12", "--arrive").action shouldBe "goto"
                pod("land", "--until-landed").armed shouldBe false
                withTimeout(5.seconds) { sim.state.first { it.landedState == LandedState.ON_GROUND } }
            } finally {
                sim.stop()
            }
        }
    }

    "a refused action exits 1 with the autopilot's reason" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 52, initialCharge = 0.05, gcs = "udpout://127.0.0.1:$port"))
            try {
                sim.start(this)
                val out = Lines()
                val error = shouldThrow<CliktError> {
                    withContext(Dispatchers.IO) { Pod(out).parse(listOf("arm", "--connect", "udpin:127.0.0.1:$port", "--sysid", "52", "--json")) }
                }
                error.statusCode shouldBe 1
                // ArduPilot sends the reason after the COMMAND_ACK; it must still be shown. A flat
                // battery cannot clear by waiting, so the booting vehicle is not waited for.
                error.message!! shouldContain "MAV_CMD_COMPONENT_ARM_DISARM was FAILED: "
                error.message!! shouldContain "PreArm: Battery 1 below minimum arming voltage"
                out.events.last().shouldBeInstanceOf<Event.Error>().message shouldContain "PreArm: Battery 1 below minimum arming voltage"
            } finally {
                sim.stop()
            }
        }
    }

    "an unknown mode is refused with the modes the vehicle has" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 53, gcs = "udpout://127.0.0.1:$port"))
            try {
                sim.start(this)
                val error = shouldThrow<CliktError> {
                    withContext(Dispatchers.IO) { Pod(Lines()).parse(listOf("mode", "WARP", "--connect", "udpin:127.0.0.1:$port", "--sysid", "53")) }
                }
                error.message!! shouldContain "has no mode \"WARP\""
                error.message!! shouldContain "LOITER"
            } finally {
                sim.stop()
            }
        }
    }
})
