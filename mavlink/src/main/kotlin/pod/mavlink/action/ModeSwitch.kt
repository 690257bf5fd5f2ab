package pod.mavlink.action

import io.dronefleet.mavlink.common.MavMode
import io.dronefleet.mavlink.common.SetMode
import io.dronefleet.mavlink.util.EnumValue
import pod.core.vehicle.Autopilot
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.CommandResult
import pod.mavlink.command.MavCommandParams.MODE_FLAG_CUSTOM_MODE_ENABLED
import pod.mavlink.command.MavCommands.DO_SET_MODE
import pod.mavlink.command.VehicleCommand
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.telemetry.Px4CustomMode

/**
 * Mode changes by name, confirmed by the heartbeat ([VehicleActions.setMode]): DO_SET_MODE with
 * the custom mode as the autopilot takes it (PX4 its main and sub mode apart, [Px4CustomMode]),
 * the SET_MODE message for an autopilot too old for the command, and refusals of a vehicle still
 * initialising waited out ([Readiness]).
 */
internal class ModeSwitch(private val vehicle: MavlinkVehicle, private val readiness: Readiness, private val waits: StateWaits) {
    /** Switches to the mode called [name] and waits until the heartbeat reports it. */
    suspend fun setMode(name: String) {
        val (autopilot, type) = vehicle.airframe()
        val custom = FlightModes.customMode(autopilot, type, name)
            ?: throw UnknownMode(name, autopilot, type, FlightModes.names(autopilot, type))
        if (vehicle.telemetry.mode.value?.customMode == custom) return
        // The command's form follows the custom-mode numbering ([FlightModes]), a codec fact, not behaviour.
        val command = if (autopilot == Autopilot.PX4) {
            VehicleCommand(DO_SET_MODE, param1 = MODE_FLAG_CUSTOM_MODE_ENABLED.toFloat(), param2 = Px4CustomMode.main(custom).toFloat(), param3 = Px4CustomMode.sub(custom).toFloat())
        } else {
            VehicleCommand(DO_SET_MODE, param1 = MODE_FLAG_CUSTOM_MODE_ENABLED.toFloat(), param2 = custom.toFloat())
        }
        try {
            readiness.retry("switch to $name", { ArmReadiness.modeWaitFor(it.statusTexts, readiness.initialising()) }) { vehicle.commands.send(command) }
        } catch (e: CommandRejected) {
            if (e.result != CommandResult.UNSUPPORTED) throw e
            // Autopilots older than DO_SET_MODE take the (unacknowledged) SET_MODE message.
            vehicle.send(SetMode.builder().targetSystem(vehicle.systemId).baseMode(EnumValue.create<MavMode>(1)).customMode(custom).build())
        }
        waits.confirm("set mode $name", "mode $name", vehicle.telemetry.mode) { it?.customMode == custom }
    }
}
