package pod.e2e

import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.parse
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeLessThan
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import pod.cli.Pod
import pod.cli.json.Event
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.e2e.Flights.item
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.MavCommands.NAV_TAKEOFF
import pod.mavlink.command.MavCommands.NAV_WAYPOINT
import pod.mavlink.command.VehicleCommand
import pod.mavlink.mission.MissionType
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * What the vehicle says and the preconditions it reports, as `pod` turns them into answers for
 * people: fast, one sentence, never an internal object or a raw duration.
 */
class VehicleAnswersCliSpec : StringSpec({

    /** Runs `pod` against [sim] (listening on [port]); the error it ended with, if any, and its lines. */
    suspend fun pod(port: Int, vararg args: String): Pair<CliktError?, List<String>> {
        val out = Lines()
        val error = try {
            withContext(Dispatchers.IO) { Pod(out).parse(args.toList() + listOf("--connect", "udpin:127.0.0.1:$port")) }
            null
        } catch (e: CliktError) {
            e
        }
        return error to out.lines
    }

    suspend fun withSim(config: SimVehicleConfig, block: suspend CoroutineScope.(SimVehicle, Int) -> Unit) = coroutineScope {
        val port = freePort()
        val sim = SimVehicle(config.copy(gcs = "udpout://127.0.0.1:$port"))
        try {
            sim.start(this)
            block(sim, port)
        } finally {
            sim.stop()
        }
    }

    "a fraction written to an integer parameter is reported as the whole number the vehicle stored, exit 0" {
        withSim(SimVehicleConfig(systemId = 61)) { _, port ->
            val (error, lines) = pod(port, "param", "set", "DISARM_DELAY", "2.7")
            error shouldBe null
            lines.last() shouldBe "DISARM_DELAY is an integer parameter (INT8): the vehicle stored 3 for 2.7"
        }
    }

    "a value an integer parameter's type cannot hold is refused before anything is written, exit 2" {
        withSim(SimVehicleConfig(systemId = 62)) { _, port ->
            val (error, _) = pod(port, "param", "set", "DISARM_DELAY", "300")
            error!!.statusCode shouldBe 2
            error.message!! shouldContain "DISARM_DELAY is an integer parameter (INT8) holding -128..127: 300 does not fit"
            pod(port, "param", "get", "DISARM_DELAY").second.last() shouldBe "DISARM_DELAY = 10 (INT8)"
        }
    }

    "start on a disarmed copter fails at once with what to do and leaves its mode as it was" {
        withSim(SimVehicleConfig(systemId = 63)) { sim, port ->
            sim.missionServer.load(MissionType.MISSION, Flights.copterSurvey(SimVehicleConfig.DEFAULT_HOME))
            val mode = withTimeout(10.seconds) { sim.state.first { it.modeName.isNotEmpty() } }.modeName
            val (error, _) = pod(port, "start", "--sysid", "63")
            error!!.statusCode shouldBe 1
            error.message shouldBe "error: vehicle 63 is disarmed: arm it first with `pod arm`, or pass --arm"
            sim.state.value.modeName shouldBe mode
        }
    }

    "start --arm arms a disarmed copter and starts its mission" {
        withSim(SimVehicleConfig(systemId = 71, parameters = mapOf("DISARM_DELAY" to 0.0))) { sim, port ->
            sim.missionServer.load(MissionType.MISSION, Flights.copterSurvey(SimVehicleConfig.DEFAULT_HOME))
            val (error, lines) = pod(port, "start", "--arm")
            error shouldBe null
            lines.last() shouldBe "vehicle 71: mission started"
            sim.state.value.armed shouldBe true
            sim.state.value.modeName shouldBe "AUTO"
        }
    }

    "start --from beyond the vehicle's mission fails fast, naming the items it holds" {
        val home = SimVehicleConfig.DEFAULT_HOME
        withSim(SimVehicleConfig(systemId = 64, autopilot = Autopilot.PX4)) { sim, port ->
            sim.missionServer.load(MissionType.MISSION, (0 until 6).map { item(it, NAV_WAYPOINT, home.offset((10 * it).m, 0.m), 20.0) })
            val started = TimeSource.Monotonic.markNow()
            val (error, _) = pod(port, "start", "--from", "99")
            error!!.statusCode shouldBe 1
            error.message!! shouldContain "vehicle 64 holds 6 mission items (0..5): there is no item 99 to start from"
            started.elapsedNow() shouldBeLessThan 10.seconds
            sim.state.value.armed shouldBe false
        }
    }

    "--wait bounds the wait for a heartbeat only: a vehicle heard within it is picked without --sysid" {
        withSim(SimVehicleConfig(systemId = 65)) { sim, port ->
            val (error, lines) = pod(port, "mode", "GUIDED", "--wait", "1.5s")
            error shouldBe null
            lines.last() shouldBe "vehicle 65: mode GUIDED"
            sim.state.value.modeName shouldBe "GUIDED"
        }
    }

    "waiting for a --sysid that never answers says whom it heard, while it waits and when it gives up" {
        withSim(SimVehicleConfig(systemId = 70)) { _, port ->
            val (error, lines) = pod(port, "arm", "--sysid", "42", "--wait", "3s")
            error!!.statusCode shouldBe 1
            error.message shouldBe "error: no heartbeat from vehicle 42 within 3.0 s; heard 70"
            lines.first() shouldContain Regex("^waiting for vehicle 42 \\(2\\.\\d s of 3\\.0 s\\) — heard 70$")
        }
    }

    "pod takeoff on a PX4 vehicle that disarmed itself arms it and takes off, saying so (it does not sit in Takeoff mode on the ground)" {
        // PX4 disarms a vehicle left armed on the ground after COM_DISARM_PRFLT seconds; disarmed, it
        // accepts NAV_TAKEOFF and only changes mode (Commander), so the take-off path arms it first.
        withSim(SimVehicleConfig(systemId = 66, autopilot = Autopilot.PX4, parameters = mapOf("COM_DISARM_PRFLT" to 3.0))) { sim, port ->
            pod(port, "arm").first shouldBe null
            withTimeout(10.seconds) { sim.state.first { !it.armed } }
            val (error, lines) = pod(port, "takeoff", "20")
            error shouldBe null
            lines.last() shouldContain "at 20.0 m (armed)"
            (sim.state.value.relativeAltitude.meters > 19.0) shouldBe true
        }
    }

    "a silent exchange says what is awaited while it lasts, and its failure gives a rounded duration" {
        withSim(SimVehicleConfig(systemId = 67)) { _, port ->
            val (error, lines) = pod(port, "param", "get", "NO_SUCH_PARAM", "--json")
            error!!.statusCode shouldBe 1
            error.message!! shouldContain Regex("after \\d+ requests over 10\\.\\d s: ")
            // Every --json line is an event of the model; the waits are `waiting` events.
            val waiting = lines.map(::decodeEvent).filterIsInstance<Event.Waiting>().filter { it.reason == "parameter NO_SUCH_PARAM" }
            (waiting.size >= 2) shouldBe true
            waiting.first().sysid shouldBe 67
            waiting.first().timeoutS shouldBe 10.0
            waiting.last().attempt!! shouldBeGreaterThan waiting.first().attempt!!
        }
    }

    "a takeoff an ArduCopter refuses for its mode says to switch to GUIDED and how" {
        Flights.flying(SimVehicleConfig(systemId = 68)) { v, sim ->
            Flights.keepArmedOnGround(v)
            v.action.setMode("STABILIZE")
            v.action.arm()
            val refused = shouldThrow<CommandRejected> { v.commands.send(VehicleCommand(NAV_TAKEOFF, param7 = 10f)) }
            refused.message!! shouldContain "vehicle 68 is in STABILIZE: switch with `pod mode GUIDED`"
            sim.state.value.relativeAltitude.meters shouldBeLessThan 1.0
        }
    }

    "resume on a disarmed copter on the ground is refused with what to do, and its mode is left as it was" {
        withSim(SimVehicleConfig(systemId = 72)) { sim, port ->
            sim.missionServer.load(MissionType.MISSION, Flights.copterSurvey(SimVehicleConfig.DEFAULT_HOME))
            val mode = withTimeout(10.seconds) { sim.state.first { it.modeName.isNotEmpty() } }.modeName
            val (error, _) = pod(port, "resume")
            error!!.statusCode shouldBe 1
            error.message shouldBe "error: vehicle 72 is disarmed on the ground: there is no mission or goto in flight to resume; " +
                "start the mission with `pod start --arm`"
            sim.state.value.modeName shouldBe mode
        }
    }

    "start --from beyond the mission with --arm refuses before arming" {
        withSim(SimVehicleConfig(systemId = 73)) { sim, port ->
            sim.missionServer.load(MissionType.MISSION, Flights.copterSurvey(SimVehicleConfig.DEFAULT_HOME))
            val (error, _) = pod(port, "start", "--from", "9", "--arm")
            error!!.statusCode shouldBe 1
            error.message!! shouldContain "there is no item 9 to start from"
            sim.state.value.armed shouldBe false
        }
    }

    "goto and pause on a disarmed copter on the ground say why and what to do, not a bare FAILED" {
        withSim(SimVehicleConfig(systemId = 74)) { sim, port ->
            val mode = withTimeout(10.seconds) { sim.state.first { it.modeName.isNotEmpty() } }.modeName
            val home = SimVehicleConfig.DEFAULT_HOME
            val (gotoError, _) = pod(port, "goto", "${home.latitude}", "${home.longitude}", "20")
            gotoError!!.statusCode shouldBe 1
            gotoError.message shouldBe "error: vehicle 74 is disarmed: arm it first with `pod arm`, then take off with `pod takeoff ALT`"
            sim.state.value.modeName shouldBe mode
            val (pauseError, _) = pod(port, "pause")
            pauseError!!.statusCode shouldBe 1
            pauseError.message shouldBe "error: vehicle 74 is disarmed on the ground: there is no mission or goto in flight to pause; " +
                "start a mission with `pod start --arm`"
        }
    }
})
