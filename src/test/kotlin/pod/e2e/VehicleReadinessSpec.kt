package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.engine.Engine
import pod.core.engine.EngineConfig
import pod.core.engine.PickRequest
import pod.core.vehicle.VehicleType
import pod.mavlink.GroundStation
import pod.mavlink.command.CommandRejected
import pod.mavlink.platform.MavlinkPlatform
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.seconds

/**
 * Vehicles that are still booting, behind a real UDP link: the simulated ArduPilot has no home
 * until its estimator sets an origin and refuses to arm until its sensors settle, as ArduPilot
 * SITL does (in simulated seconds, at a time scale that keeps the test short).
 */
class VehicleReadinessSpec : StringSpec({

    "a vehicle picked on a real link has its home and position, even when its home comes seconds after its first heartbeat" {
        virtualRun { coroutineScope {
            val gcs = station(this)
            val sim = vehicle(SimVehicleConfig(systemId = 61, positionReadyAfter = 3.seconds), gcs)
            try {
                sim.start(this)
                val platform = MavlinkPlatform(gcs)
                val heard = withTimeout(5.seconds) { gcs.vehicles.first { 61 in it } }.getValue(61)
                withTimeout(5.seconds) { platform.initialising.first { 61 in it } }.getValue(61) shouldContain "home"
                val home = Engine(platform, EngineConfig(timebase = timebase)).run {
                    val v = pick(PickRequest(count = 1, timeout = 10.seconds))[0]
                    v.position.value.shouldNotBeNull()
                    v.home.value // what `v.home.value!!` in the README reads
                }
                home.shouldNotBeNull()
                heard.telemetry.home.value shouldBe home
                platform.initialising.value shouldBe emptyMap()
            } finally {
                sim.stop()
                gcs.close()
            }
        } }
    }

    "arming a vehicle whose sensors are still settling waits, saying why, and arms once they are ready" {
        val config = SimVehicleConfig(systemId = 62, type = VehicleType.FIXED_WING, positionReadyAfter = 1.seconds, sensorsReadyAfter = 4.seconds)
        virtualRun { flying(config) { v, _ ->
            coroutineScope {
                val shown = async(start = CoroutineStart.UNDISPATCHED) { v.action.waitingFor.filterNotNull().first() }
                withTimeout(15.seconds) { v.action.arm() }
                v.telemetry.armed.value shouldBe true
                shown.await() shouldBe "Arm: Accels inconsistent"
                v.action.waitingFor.value shouldBe null
            }
        } }
    }

    "a refusal that waiting cannot clear fails at once with the autopilot's reason, sent after its COMMAND_ACK" {
        virtualRun { flying(SimVehicleConfig(systemId = 63, initialCharge = 0.05)) { v, _ ->
            val error = shouldThrow<CommandRejected> { withTimeout(3.seconds) { v.action.arm() } }
            error.statusTexts shouldContain "PreArm: Battery 1 below minimum arming voltage"
            error.message!! shouldContain "FAILED: PreArm: Battery 1 below minimum arming voltage"
            error.attempts shouldBe 1
        } }
    }
})
