package pod.sim.autopilot

import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.MavFrames
import pod.mavlink.command.CommandResult
import pod.mavlink.command.CommandResult.ACCEPTED
import pod.mavlink.command.CommandResult.DENIED
import pod.mavlink.command.CommandResult.FAILED
import pod.mavlink.command.MavCommandParams.REPOSITION_FLAG_CHANGE_MODE
import pod.core.vehicle.Severity

/** How a command handler explains itself and reuses the mode and arming logic of [Commands]. */
internal interface CommandReplies {
    /** Queues a line explaining a refusal, sent with the ack. */
    fun refuse(text: String, severity: Severity = Severity.CRITICAL)

    /** Switches to mode [name] when the profile allows it now: ACCEPTED or the refusal. */
    fun modeResult(name: String): CommandResult

    /** Every line refusing an arm now (empty: it may arm). */
    fun armingProblems(): List<String>

    /** Queues a line that follows the ack. */
    fun followUp(text: String)
}

/**
 * The commands that fly the vehicle somewhere: take-off, the landing sequence, DO_REPOSITION,
 * MISSION_START and DO_SET_MISSION_CURRENT, each answered as the vehicle's profile says.
 */
internal class GuidedCommands(private val ap: FlightControl, private val replies: CommandReplies) {
    private val profile get() = ap.profile

    /** NAV_TAKEOFF, as the profile's firmware takes it. */
    fun takeoff(cmd: CommandRequest): CommandResult = profile.takeoff(cmd, ap, replies)

    /** MISSION_START, as the profile's firmware takes it. */
    fun missionStart(cmd: CommandRequest): CommandResult = profile.missionStart(cmd, ap, replies)

    /** DO_LAND_START: flies the mission from its first DO_LAND_START in the profile's landing mode. */
    fun landStart(): CommandResult {
        val index = ap.mission.landStartIndex() ?: return FAILED.also { replies.refuse("No landing sequence found", Severity.WARNING) }
        if (!ap.flying) return FAILED
        ap.setMode(profile.landStartMode)
        ap.mission.startAt(index)
        return ACCEPTED
    }

    /**
     * DO_REPOSITION: fly to a point in the profile's guided mode. The order of the checks and
     * each answer are the profile's (GCS_MAVLINK_Copter / _Plane::handle_command_int_do_reposition,
     * PX4 Commander and Navigator).
     */
    fun reposition(cmd: CommandRequest): CommandResult {
        if (profile.repositionNeedsCommandInt && !cmd.isInt) return CommandResult.UNSUPPORTED
        val changeMode = cmd.param2.toInt() and REPOSITION_FLAG_CHANGE_MODE != 0
        val guided = profile.guidedMode
        val outsideGuided = ap.modeName != guided && !changeMode
        profile.repositionOutsideGuidedFirst?.let { if (outsideGuided) return it }
        val frame = cmd.frame ?: MavFrames.GLOBAL
        if (!MavFrames.isGlobal(frame)) return DENIED
        val lat = cmd.latitude()
        val lon = cmd.longitude()
        if ((lat != null && lat !in -90.0..90.0) || (lon != null && lon !in -180.0..180.0)) return DENIED
        profile.repositionOutsideGuidedAfterChecks?.let { if (outsideGuided) return it }
        if (!ap.armed || !ap.flying) return profile.refusal
        if (profile.repositionIgnoredOutsideGuided && outsideGuided) return ACCEPTED
        val here = ap.body.location
        val alt = when {
            !cmd.z.isFinite() -> here.altitude.meters
            frame == MavFrames.GLOBAL || frame == MavFrames.GLOBAL_INT -> cmd.z.toDouble()
            else -> ap.home.altitude.meters + cmd.z
        }
        val target = Location(lat ?: here.latitude, lon ?: here.longitude, alt.m)
        if (!ap.fence.allowsDestination(target)) {
            profile.repositionOutsideFence?.let { return it }
            if (ap.modeName != guided) ap.setMode(guided)
            return ACCEPTED.also { replies.followUp("Reposition is outside geofence") }
        }
        if (ap.modeName != guided) ap.setMode(guided)
        ap.fly(profile.guidedGoTo(cmd, target, ap))
        return ACCEPTED
    }

    /** DO_SET_MISSION_CURRENT: the same as MISSION_SET_CURRENT (GCS_MAVLINK::handle_command_do_set_mission_current). */
    fun setCurrent(cmd: CommandRequest): CommandResult {
        val seq = cmd.param1.toInt()
        if (seq !in 0 until ap.missionItems.size) return DENIED
        ap.setCurrent(seq)
        if (profile.setCurrentRestartsItem && ap.activity == Activity.Mission) ap.mission.restart()
        return ACCEPTED
    }
}
