package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.flow.filter
import kotlinx.coroutines.flow.take
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.Autopilot
import pod.mavlink.GroundStationConfig
import pod.mavlink.VehicleTiming
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.CommandResult
import pod.mavlink.command.CommandTimeout
import pod.mavlink.command.CommandTiming
import pod.mavlink.command.MavCommands
import pod.mavlink.command.VehicleCommand
import pod.mavlink.param.ParamEncoding
import pod.mavlink.param.ParamTimeout
import pod.mavlink.param.ParamType

/** 2²⁴ + 1 and + 3: integers a float cannot hold, so only a bit-for-bit encoding carries them. */
private const val BIG = 16_777_217
private const val BIGGER = 16_777_219

private val PARAMS = arrayOf("--param=MY_INT=42", "--param=MY_FLOAT=1.5", "--param=NEG_INT=-7", "--param=BIG_INT=$BIG")

/** Short enough that refusals and silences end within a second or two. */
private val QUICK = CommandTiming(
    timeout = 1.seconds, initialAttemptTimeout = 200.milliseconds, maxAttemptTimeout = 400.milliseconds,
    retryDelay = 200.milliseconds, temporarilyRejectedFor = 600.milliseconds,
)

/** A station whose commands to every vehicle are [QUICK]. */
private val QUICK_COMMANDS = GroundStationConfig(vehicleTiming = VehicleTiming(commands = QUICK))

/** The next [count] events named [name] that the peer printed. */
private suspend fun JsonPeer.next(name: String, count: Int = 1): List<Map<String, String>> =
    withTimeout(5.seconds) { events.filter { it["event"] == name }.take(count).toList() }

/**
 * Pod as the ground station against MAVSDK 4's server-side plugins (mavsdk_vehicle.py with
 * ParamServer and ActionServer): parameters both ways, and the command protocol's answers.
 */
class MavsdkServerPluginsSpec : StringSpec({

    "Pod reads MAVSDK ParamServer's INT32 and float parameters bit for bit, including integers a float cannot hold" {
        withMavsdkVehicle("--no-mission-server", *PARAMS) { vehicle, _ ->
            // MAVSDK's heartbeat says MAV_AUTOPILOT_GENERIC, so Pod expects integers bytewise, and
            // MAVSDK's ParamServer sends them bytewise whatever it declares (its sender is hard-wired to PX4).
            vehicle.identity.value.autopilot shouldBe Autopilot.GENERIC
            vehicle.params.encoding shouldBe ParamEncoding.BYTEWISE

            val myInt = vehicle.params.read("MY_INT")
            myInt.value shouldBe 42.0
            myInt.type shouldBe ParamType.INT32
            myInt.count shouldBe 4
            vehicle.params.read("NEG_INT").value shouldBe -7.0
            vehicle.params.read("BIG_INT").value shouldBe BIG.toDouble()
            val myFloat = vehicle.params.read("MY_FLOAT")
            myFloat.value shouldBe 1.5
            myFloat.type shouldBe ParamType.REAL32
        }
    }

    "Pod's parameter writes reach MAVSDK's ParamServer as the values written, which reports each change" {
        withMavsdkVehicle("--no-mission-server", *PARAMS) { vehicle, peer ->
            vehicle.params.write("MY_INT", 43.0).value shouldBe 43.0
            peer.next("param_changed").single() shouldBe mapOf("event" to "param_changed", "name" to "MY_INT", "kind" to "int", "value" to "43")
            vehicle.params.write("NEG_INT", -9.0).value shouldBe -9.0
            peer.next("param_changed", 2).last()["value"] shouldBe "-9"
            vehicle.params.write("BIG_INT", BIGGER.toDouble()).value shouldBe BIGGER.toDouble()
            peer.next("param_changed", 3).last()["value"] shouldBe "$BIGGER"
            vehicle.params.write("MY_FLOAT", 2.25).value shouldBe 2.25
            peer.next("param_changed", 4).last() shouldBe mapOf("event" to "param_changed", "name" to "MY_FLOAT", "kind" to "float", "value" to "2.25")
            // Read back from MAVSDK's cache, not from the write's echo.
            vehicle.params.read("MY_INT").value shouldBe 43.0
            vehicle.params.read("BIG_INT").value shouldBe BIGGER.toDouble()
        }
    }

    "a parameter MAVSDK's ParamServer does not have is never answered, so Pod fails with ParamTimeout" {
        withMavsdkVehicle("--no-mission-server", *PARAMS, station = GroundStationConfig(vehicleTiming = VehicleTiming(params = QUICK))) { vehicle, _ ->
            val error = shouldThrow<ParamTimeout> { vehicle.params.read("NO_SUCH_PARAM") }
            error.name shouldBe "NO_SUCH_PARAM"
            error.attempts shouldBeGreaterThan 1
        }
    }

    "an armable MAVSDK ActionServer accepts Pod's arm command, reports the request and then heartbeats armed" {
        withMavsdkVehicle("--no-mission-server", "--action=armable") { vehicle, peer ->
            val reply = vehicle.commands.send(VehicleCommand(MavCommands.COMPONENT_ARM_DISARM, param1 = 1f))
            reply.result shouldBe CommandResult.ACCEPTED
            reply.command shouldBe MavCommands.COMPONENT_ARM_DISARM
            peer.next("arm_disarm").single() shouldBe mapOf("event" to "arm_disarm", "result" to "SUCCESS", "arm" to "true", "force" to "false")
            // VehicleActions.arm() resends the (idempotent) arm and waits for the armed flag in HEARTBEAT.
            vehicle.action.arm()
            vehicle.telemetry.armed.value shouldBe true
            vehicle.commands.send(VehicleCommand(MavCommands.NAV_TAKEOFF, param7 = 10f)).result shouldBe CommandResult.ACCEPTED
            peer.next("takeoff").single()["result"] shouldBe "SUCCESS"
        }
    }

    "a MAVSDK ActionServer that is not armable answers TEMPORARILY_REJECTED to every resend, and Pod gives up with CommandRejected" {
        withMavsdkVehicle("--no-mission-server", "--action=refusing", station = QUICK_COMMANDS) { vehicle, peer ->
            val error = shouldThrow<CommandRejected> { vehicle.commands.send(VehicleCommand(MavCommands.COMPONENT_ARM_DISARM, param1 = 1f)) }
            error.result shouldBe CommandResult.TEMPORARILY_REJECTED
            error.resultCode shouldBe 1
            error.attempts shouldBeGreaterThan 1
            // Each resend reached MAVSDK and was refused there.
            peer.next("arm_disarm", error.attempts).forEach {
                it["result"] shouldBe "COMMAND_DENIED"
                it["arm"] shouldBe "true"
            }
            vehicle.telemetry.armed.value shouldBe false
        }
    }

    "MAVSDK's server components leave a command they have no handler for unanswered, so Pod fails with CommandTimeout" {
        withMavsdkVehicle("--no-mission-server", "--action=armable", station = QUICK_COMMANDS) { vehicle, _ ->
            // MAV_CMD_DO_SET_SERVO: no MAVSDK server plugin handles it, and MAVSDK sends no UNSUPPORTED.
            val error = shouldThrow<CommandTimeout> { vehicle.commands.send(VehicleCommand(MavCommands.DO_SET_SERVO, param1 = 9f, param2 = 1500f)) }
            error.waitingFor shouldBe "COMMAND_ACK"
            error.attempts shouldBeGreaterThan 1
        }
    }

    "a MAVSDK ActionServer that does not allow takeoff answers UNSUPPORTED, which Pod reports at once" {
        withMavsdkVehicle("--no-mission-server", "--action=refusing") { vehicle, peer ->
            val error = shouldThrow<CommandRejected> { vehicle.commands.send(VehicleCommand(MavCommands.NAV_TAKEOFF, param7 = 10f)) }
            error.result shouldBe CommandResult.UNSUPPORTED
            error.attempts shouldBe 1
            peer.next("takeoff").single() shouldBe mapOf("event" to "takeoff", "result" to "COMMAND_DENIED", "allowed" to "false")
        }
    }
})
