package pod.sim.autopilot

import pod.core.vehicle.Severity
import pod.mavlink.command.CommandResult
import pod.mavlink.command.CommandResult.ACCEPTED
import pod.mavlink.command.CommandResult.DENIED
import pod.mavlink.command.CommandResult.FAILED
import pod.mavlink.command.CommandResult.UNSUPPORTED

/**
 * MAV_CMD_DO_PAUSE_CONTINUE as each autopilot answers it.
 *
 * ArduCopter (ArduCopter/GCS_Mavlink.cpp, GCS_MAVLINK_Copter::handle_command_pause_continue):
 * param1 0 calls the mode's pause(), 1 its resume(), ACCEPTED when it returns true, else FAILED
 * with the INFO line "Failed to pause" / "Failed to resume"; any other param1 is DENIED. Only two
 * modes have them (the Mode base class returns false): ModeAuto::pause stops a waypoint leg not
 * yet reached and ModeAuto::resume continues one that was paused (ArduCopter/mode_auto.cpp);
 * ModeGuided::pause and ::resume only set and clear `_paused` and always succeed, so a goto
 * paused in GUIDED flies on to the same destination when resumed, and a resume in GUIDED with
 * nothing paused is accepted and changes nothing (ArduCopter/mode_guided.cpp). Entering GUIDED
 * clears the pause (ModeGuided::init).
 *
 * PX4's commander has no case for it (src/modules/commander/Commander.cpp,
 * Commander::handle_command: default → UNSUPPORTED); ArduPlane does not handle it either: both
 * hold by switching mode.
 */
internal class PauseContinue(private val ap: FlightControl) {
    /** The goto a GUIDED pause stopped, and the hold that stands in for it while paused. */
    private var pausedGoto: Pair<Activity.Hold, Activity.GoTo>? = null

    /** Handles [cmd]; [refuse] queues the line explaining a refusal. */
    fun handle(cmd: CommandRequest, refuse: (String, Severity) -> Unit): CommandResult {
        if (!ap.profile.handlesPauseContinue) return UNSUPPORTED
        val ok = when (cmd.param1.toInt()) {
            0 -> pause()
            1 -> resume()
            else -> return DENIED
        }
        if (ok) return ACCEPTED
        refuse(if (cmd.param1.toInt() == 0) "Failed to pause" else "Failed to resume", Severity.INFO)
        return FAILED
    }

    private fun pause(): Boolean = when (val a = ap.activity) {
        Activity.Mission -> ap.mission.pause()
        is Activity.GoTo -> true.also {
            val hold = Activity.Hold(ap.body.location, 0.0)
            pausedGoto = hold to a
            ap.fly(hold)
        }
        else -> ap.modeName == "GUIDED"
    }

    private fun resume(): Boolean {
        if (ap.activity == Activity.Mission) return ap.mission.resume()
        if (ap.modeName != "GUIDED") return false
        // The hold a pause put in place, still current: the mode was not left meanwhile.
        pausedGoto?.let { (hold, goto) -> if (ap.activity === hold) ap.fly(goto) }
        pausedGoto = null
        return true
    }
}
