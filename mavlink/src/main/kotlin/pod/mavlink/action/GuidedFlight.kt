package pod.mavlink.action

import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.Speed
import pod.mavlink.MavFrames
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.MavCommandParams.REPOSITION_FLAG_CHANGE_MODE
import pod.mavlink.command.MavCommands.DO_REPOSITION
import pod.mavlink.command.VehicleCommand
import pod.mavlink.telemetry.ModeRole
import kotlin.math.abs
import kotlin.time.Duration

/**
 * Flying where the ground station says and stopping there ([VehicleActions.goto],
 * [VehicleActions.hold], [VehicleActions.awaitArrival]): DO_REPOSITION in the guided mode, and a
 * hold that needs nobody on the sticks.
 */
internal class GuidedFlight(private val vehicle: MavlinkVehicle, private val modes: ModeSwitch, private val waits: StateWaits) {
    /** Flies to [target] (altitude above sea level) at [speed] or the vehicle's own; returns once accepted. */
    suspend fun goto(target: Location, speed: Speed?) {
        // Before the mode change: a disarmed ArduCopter would be left in GUIDED and then refuse
        // the reposition with a bare FAILED.
        waits.requireArmed("fly to a point")
        val guided = vehicle.modeFor(ModeRole.GUIDED)
        if (!vehicle.firmware().repositionSwitchesMode) modes.setMode(guided)
        vehicle.commands.send(
            VehicleCommand(
                DO_REPOSITION,
                param1 = speed?.metersPerSecond?.toFloat() ?: -1f,
                param2 = REPOSITION_FLAG_CHANGE_MODE.toFloat(),
                param4 = Float.NaN,
                param5 = target.latitude, param6 = target.longitude, param7 = target.altitude.meters.toFloat(),
                frame = MavFrames.GLOBAL_INT,
            ),
        )
        waits.confirm("goto", "mode $guided", vehicle.telemetry.mode) { it?.name == guided }
    }

    /** Stops and holds position and altitude in the hold mode, and waits until the heartbeat shows it. */
    suspend fun hold() {
        val hold = vehicle.modeFor(ModeRole.HOLD)
        val here = vehicle.telemetry.position.value
        // PX4's Hold is also where a goto flies (DO_REPOSITION in AUTO.LOITER), and choosing the
        // mode a vehicle is already in changes nothing: a reposition stops it there (PX4
        // src/modules/navigator/loiter.cpp Loiter::on_active -> reposition()). Onto where it can
        // stop, not where it was heard: that point is behind a moving vehicle by its braking distance.
        if (hold == vehicle.modeFor(ModeRole.GUIDED) && vehicle.telemetry.mode.value?.name == hold && vehicle.telemetry.armed.value && here != null) {
            goto(StoppingPoint.of(here), null)
            return
        }
        modes.setMode(hold)
    }

    /** Waits until the vehicle is within [within] of [target] horizontally and vertically. */
    suspend fun awaitArrival(target: Location, within: Distance, timeout: Duration) {
        waits.confirm("arrival at $target", "within $within", vehicle.telemetry.position, timeout) { p ->
            p != null && p.location.copy(altitude = target.altitude).distanceTo(target).meters <= within.meters &&
                abs(p.location.altitude.meters - target.altitude.meters) <= within.meters
        }
    }
}
