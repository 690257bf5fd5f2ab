package pod.sim.autopilot.profile

import pod.mavlink.MavFrames
import pod.mavlink.command.CommandResult
import pod.mavlink.command.CommandResult.ACCEPTED
import pod.mavlink.command.CommandResult.DENIED
import pod.mavlink.command.CommandResult.FAILED
import pod.sim.autopilot.Activity
import pod.sim.autopilot.CommandReplies
import pod.sim.autopilot.CommandRequest
import pod.sim.autopilot.FlightControl

/**
 * ArduPilot's NAV_TAKEOFF (GCS_MAVLINK_Copter / _Plane::handle_command_nav_takeoff): a
 * COMMAND_INT only in GLOBAL_RELATIVE_ALT, only armed on the ground, z metres above home. A
 * copter takes off in the modes [takeoffModes] allows and holds in the same mode; a plane
 * switches to TAKEOFF (TKOFF_ALT when z is not positive) and then LOITER.
 */
internal fun ArduPilotProfile.arduTakeoff(cmd: CommandRequest, vehicle: FlightControl, takeoffModes: Set<String>?): CommandResult {
    if (cmd.isInt && cmd.frame != MavFrames.GLOBAL_RELATIVE_ALT) return DENIED
    if (!vehicle.armed || vehicle.flying) return FAILED
    val altitude = vehicle.home.altitude.meters + cmd.z.toDouble()
    if (takeoffModes != null) {
        if (vehicle.modeName !in takeoffModes) return FAILED
        vehicle.fly(Activity.Takeoff(altitude, afterTakeoffMode))
    } else {
        vehicle.setMode("TAKEOFF")
        vehicle.fly(Activity.Takeoff(if (cmd.z > 0) altitude else vehicle.takeoffAltitude(null), afterTakeoffMode))
    }
    return ACCEPTED
}

/** ArduPilot's MISSION_START: first/last item unsupported (DENIED), else AUTO as DO_SET_MODE would select it. */
internal fun arduMissionStart(cmd: CommandRequest, replies: CommandReplies): CommandResult {
    if (cmd.param1 != 0f || cmd.param2 != 0f) return DENIED
    return if (replies.modeResult("AUTO") == ACCEPTED) ACCEPTED else FAILED
}

/** PX4's NAV_TAKEOFF and MISSION_START (Commander and Navigator). */
internal object Px4Commands {
    /**
     * NAV_TAKEOFF: z is AMSL (NaN: MIS_TAKEOFF_ALT above home); refused before a position
     * estimate. Every NAV_TAKEOFF sets Navigator's takeoff setpoint to its altitude (PX4
     * navigator_main.cpp, VEHICLE_CMD_NAV_TAKEOFF -> get_takeoff_triplet()), a resend after a lost
     * ack too: re-entering AUTO.TAKEOFF above MIS_TAKEOFF_ALT must not end the climb.
     */
    fun takeoff(cmd: CommandRequest, vehicle: FlightControl, replies: CommandReplies): CommandResult {
        val amsl = cmd.z.takeIf { it.isFinite() }?.toDouble() ?: vehicle.takeoffAltitude(null)
        if (!vehicle.flying && !vehicle.positionReady) return CommandResult.TEMPORARILY_REJECTED.also { replies.refuse("Takeoff denied! Please disarm and retry") }
        vehicle.setMode("AUTO.TAKEOFF")
        if (vehicle.activity is Activity.Takeoff || vehicle.flying) vehicle.fly(Activity.Takeoff(maxOf(amsl, vehicle.ground + 1.0), Px4Profile.HOLD))
        return ACCEPTED
    }

    /**
     * MISSION_START (Commander, VEHICLE_CMD_MISSION_START): needs a valid mission; param1, the
     * first item, must be in -1 until the mission's seq_total; it arms when disarmed (refused as
     * an arm would be) and switches to AUTO.MISSION.
     */
    fun missionStart(cmd: CommandRequest, vehicle: FlightControl, replies: CommandReplies): CommandResult {
        if (!vehicle.mission.hasMission()) return CommandResult.TEMPORARILY_REJECTED.also { replies.refuse("Mission start denied! No valid mission") }
        val firstItem = cmd.param1.toInt()
        if (firstItem >= vehicle.missionItems.size) return DENIED
        if (!vehicle.armed) {
            replies.armingProblems().takeIf { it.isNotEmpty() }?.let { problems ->
                problems.forEach { replies.refuse(it) }
                return CommandResult.TEMPORARILY_REJECTED
            }
            vehicle.arm()
        }
        if (firstItem >= 0) vehicle.setCurrent(firstItem)
        vehicle.setMode("AUTO.MISSION")
        return ACCEPTED
    }
}
