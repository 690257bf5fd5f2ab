package pod.mavlink

import pod.mavlink.action.ActionTiming
import pod.mavlink.command.CommandTiming
import pod.mavlink.mission.TransferTiming

/**
 * Timeouts and retries of what a [GroundStation] does with each vehicle it finds, fixed when the
 * vehicle is found ([GroundStationConfig.vehicleTiming]): every service of a [MavlinkVehicle] is
 * made with its part, so an exchange under way never sees its deadlines change.
 */
public data class VehicleTiming(
    /** Commands and their acknowledgements ([MavlinkVehicle.commands]). */
    public val commands: CommandTiming = CommandTiming(),
    /** Parameter reads and writes ([MavlinkVehicle.params]). */
    public val params: CommandTiming = CommandTiming(),
    /** Mission, fence and rally transfers ([MavlinkVehicle.mission]). */
    public val transfers: TransferTiming = TransferTiming(),
    /** How long actions wait for their confirmation and for a vehicle still initialising ([MavlinkVehicle.action]). */
    public val actions: ActionTiming = ActionTiming(),
)
