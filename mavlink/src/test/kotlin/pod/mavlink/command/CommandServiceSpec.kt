package pod.mavlink.command

import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.MavParamType
import io.dronefleet.mavlink.common.MavSeverity
import io.dronefleet.mavlink.common.ParamRequestRead
import io.dronefleet.mavlink.common.ParamSet
import io.dronefleet.mavlink.common.ParamValue
import io.dronefleet.mavlink.common.Statustext
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.VehicleLost
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.runTest
import pod.core.time.Timebase
import pod.mavlink.GroundStation
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkEnums
import pod.mavlink.MavlinkVehicle
import pod.mavlink.VehicleTiming
import pod.mavlink.param.ParamEncoding
import pod.mavlink.param.ParamTimeout
import pod.mavlink.param.ParamType
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

private const val ARM = 400

private fun ack(command: Int, result: CommandResult, progress: Int? = null, target: Int = 255) = CommandWire.ack(command, result, target, 190, progress)

/** A station's configuration with no stream or payload requests, and [timing] for its vehicles. */
private fun quiet(timing: VehicleTiming = VehicleTiming(), lostAfter: Duration = 3.seconds) =
    GroundStationConfig(streamRates = emptyMap(), requestPayloads = false, lostAfter = lostAfter, vehicleTiming = timing)

/** A ground station and one scripted vehicle in virtual time: the commands' timeouts and resends are the subject, not the socket. */
private fun withVehicle(
    config: GroundStationConfig = quiet(),
    autopilot: Int = MavlinkEnums.MAV_AUTOPILOT_ARDUPILOTMEGA,
    answer: suspend (Any) -> List<Any>,
    block: suspend CoroutineScope.(MavlinkVehicle, ScriptedVehicle) -> Unit,
) = ScriptedVehicle.inVirtualTime(config, autopilot, answer = answer, block = block)

class CommandServiceSpec : StringSpec({

    "a command whose first sends are lost is resent with confirmation 1, 2 and accepted" {
        withVehicle(quiet(VehicleTiming(commands = CommandTiming(initialAttemptTimeout = 100.milliseconds))), answer = { m -> if (m is CommandLong && m.confirmation() >= 2) listOf(ack(m.command().value(), CommandResult.ACCEPTED)) else emptyList() }) { v, sim ->
            v.commands.send(VehicleCommand(ARM, param1 = 1f)).result shouldBe CommandResult.ACCEPTED
            sim.commands.value shouldBe listOf(ARM to 0, ARM to 1, ARM to 2)
        }
    }

    "a refusal carries the autopilot's STATUSTEXT explanation" {
        withVehicle(answer = { m ->
            if (m !is CommandLong) emptyList() else listOf(
                Statustext.builder().severity(MavSeverity.MAV_SEVERITY_CRITICAL).text("PreArm: Need 3D Fix").build(),
                Statustext.builder().severity(MavSeverity.MAV_SEVERITY_INFO).text("chatter").build(),
                ack(m.command().value(), CommandResult.FAILED),
            )
        }) { v, _ ->
            val error = shouldThrow<CommandRejected> { v.commands.send(VehicleCommand(ARM, param1 = 1f)) }
            error.result shouldBe CommandResult.FAILED
            error.statusTexts shouldBe listOf("PreArm: Need 3D Fix")
            error.message shouldBe "MAV_CMD_COMPONENT_ARM_DISARM was FAILED: PreArm: Need 3D Fix"
        }
    }

    "ArduPilot's order: the lines after the refusing ACK explain it too; a line repeated ten times (PX4) is shown once" {
        withVehicle(answer = { m ->
            if (m !is CommandLong) emptyList() else listOf(
                ack(m.command().value(), CommandResult.FAILED),
                Statustext.builder().severity(MavSeverity.MAV_SEVERITY_CRITICAL).text("Arm: Accels inconsistent").build(),
                Statustext.builder().severity(MavSeverity.MAV_SEVERITY_CRITICAL).text("Arm: AHRS: waiting for home").build(),
            ) + List(10) { Statustext.builder().severity(MavSeverity.MAV_SEVERITY_CRITICAL).text("Arm: AHRS: waiting for home").build() }
        }) { v, _ ->
            val error = shouldThrow<CommandRejected> { v.commands.send(VehicleCommand(ARM, param1 = 1f)) }
            error.statusTexts shouldBe listOf("Arm: Accels inconsistent", "Arm: AHRS: waiting for home")
            error.message shouldBe "MAV_CMD_COMPONENT_ARM_DISARM was FAILED: Arm: Accels inconsistent; Arm: AHRS: waiting for home"
        }
    }

    "a line repeated with a trailing tab (PX4's event marker) is still shown once" {
        withVehicle(answer = { m ->
            if (m !is CommandLong) emptyList() else listOf(
                Statustext.builder().severity(MavSeverity.MAV_SEVERITY_CRITICAL).text("Arming denied: mode not armable\t").build(),
                Statustext.builder().severity(MavSeverity.MAV_SEVERITY_CRITICAL).text("Arming denied: mode not armable").build(),
                ack(m.command().value(), CommandResult.DENIED),
            )
        }) { v, _ ->
            val error = shouldThrow<CommandRejected> { v.commands.send(VehicleCommand(ARM, param1 = 1f)) }
            error.message shouldBe "MAV_CMD_COMPONENT_ARM_DISARM was DENIED: Arming denied: mode not armable"
        }
    }

    "IN_PROGRESS is a flow of progress ending with the final ACCEPTED, without resending" {
        withVehicle(answer = { m ->
            if (m !is CommandLong) emptyList() else listOf(
                ack(241, CommandResult.IN_PROGRESS, 30),
                ack(241, CommandResult.IN_PROGRESS, 60),
                ack(241, CommandResult.ACCEPTED),
            )
        }) { v, sim ->
            val progress = v.commands.sending(VehicleCommand(241, param3 = 1f)).toList()
            progress.map { it.percent } shouldBe listOf(30, 60, 60)
            progress.dropLast(1).all { it.reply == null } shouldBe true
            progress.last().reply?.result shouldBe CommandResult.ACCEPTED
            sim.commands.value shouldBe listOf(241 to 0)
        }
    }

    "acknowledgements addressed to another ground station are not ours" {
        withVehicle(quiet(VehicleTiming(commands = CommandTiming(initialAttemptTimeout = 100.milliseconds))), answer = { m ->
            if (m !is CommandLong) emptyList() else if (m.confirmation() == 0) listOf(ack(ARM, CommandResult.DENIED, target = 254)) else listOf(ack(ARM, CommandResult.ACCEPTED))
        }) { v, _ ->
            v.commands.send(VehicleCommand(ARM)).result shouldBe CommandResult.ACCEPTED
        }
    }

    "different commands run at once; the same command queues" {
        withVehicle(answer = { m -> if (m is CommandLong) listOf(ack(m.command().value(), CommandResult.ACCEPTED)) else emptyList() }) { v, sim ->
            listOf(176, 178, ARM, ARM, 179).map { c -> async { v.commands.send(VehicleCommand(c)) } }.awaitAll()
                .map { it.command } shouldBe listOf(176, 178, ARM, ARM, 179)
            sim.commands.value.count { it.first == ARM } shouldBe 2
        }
    }

    "a vehicle that never answers fails the command within its timeout; one that falls silent is lost" {
        val quick = CommandTiming(timeout = 1.seconds, initialAttemptTimeout = 100.milliseconds, maxAttemptTimeout = 300.milliseconds)
        withVehicle(config = quiet(VehicleTiming(commands = quick), lostAfter = 500.milliseconds), answer = { emptyList() }) { v, _ ->
            val error = shouldThrow<CommandTimeout> { withTimeout(3.seconds) { v.commands.send(VehicleCommand(ARM)) } }
            error.waitingFor shouldBe "COMMAND_ACK"
            (error.attempts >= 4) shouldBe true
        }
        withVehicle(config = quiet(VehicleTiming(commands = CommandTiming(timeout = 60.seconds)), lostAfter = 500.milliseconds), answer = { emptyList() }) { v, sim ->
            sim.silence()
            shouldThrow<VehicleLost> { withTimeout(5.seconds) { v.commands.send(VehicleCommand(ARM)) } }.message shouldContain "MAV_CMD_COMPONENT_ARM_DISARM"
        }
    }

    "a command left unanswered is shown as awaited while Pod resends it, and no longer once it ends" {
        withVehicle(quiet(VehicleTiming(commands = CommandTiming(timeout = 4.seconds))), answer = { emptyList() }) { v, _ ->
            val seen = java.util.concurrent.CopyOnWriteArrayList<pod.mavlink.Awaiting>()
            val watching = launch { v.awaiting.collect { if (it != null) seen += it } }
            shouldThrow<CommandTimeout> { v.commands.send(VehicleCommand(ARM)) }.message shouldContain Regex("after \\d+ sends and 4\\.\\d s waiting")
            watching.cancel()
            v.awaiting.value shouldBe null
            seen.map { it.what }.toSet() shouldBe setOf("MAV_CMD_COMPONENT_ARM_DISARM")
            (seen.last().attempt > seen.first().attempt) shouldBe true
            (seen.first().waited >= 2.seconds) shouldBe true
            seen.first().giveUpAfter shouldBe 4.seconds
            seen.first().describe() shouldContain Regex("^no answer to MAV_CMD_COMPONENT_ARM_DISARM from vehicle 1 yet \\(attempt \\d+, \\d\\.\\d s of 4\\.0 s\\)$")
        }
    }

    "parameters: PX4's bytewise integers are read and written exactly; a missing one times out" {
        val stored = HashMap(mapOf("MAV_SYS_ID" to 1.0, "MPC_XY_CRUISE" to 5.0))
        val types = mapOf("MAV_SYS_ID" to ParamType.INT32, "MPC_XY_CRUISE" to ParamType.REAL32)
        fun value(name: String) = ParamValue.builder().paramId(name).paramType(EnumValue.create<MavParamType>(types.getValue(name).mavValue))
            .paramValue(ParamEncoding.BYTEWISE.encode(stored.getValue(name), types.getValue(name))).paramCount(2).paramIndex(types.keys.indexOf(name)).build()
        val quickParams = CommandTiming(timeout = 1.seconds, initialAttemptTimeout = 100.milliseconds)
        withVehicle(quiet(VehicleTiming(params = quickParams)), autopilot = MavlinkEnums.MAV_AUTOPILOT_PX4, answer = { m ->
            when (m) {
                is ParamRequestRead -> if (m.paramId() in stored) listOf(value(m.paramId())) else emptyList()
                is ParamSet -> if (m.paramId() in stored) {
                    stored[m.paramId()] = ParamEncoding.BYTEWISE.decode(m.paramValue(), ParamType.of(m.paramType().value())!!)
                    listOf(value(m.paramId()))
                } else emptyList()
                else -> emptyList()
            }
        }) { v, _ ->
            v.params.encoding shouldBe ParamEncoding.BYTEWISE
            v.params.read("MAV_SYS_ID").value shouldBe 1.0
            v.params.write("MAV_SYS_ID", 16_777_217.0).value shouldBe 16_777_217.0 // not representable as a float value
            stored["MAV_SYS_ID"] shouldBe 16_777_217.0
            v.params.write("MPC_XY_CRUISE", 7.5).type shouldBe ParamType.REAL32
            shouldThrow<ParamTimeout> { v.params.read("NO_SUCH_PARAM") }.name shouldBe "NO_SUCH_PARAM"
        }
    }
})
