package pod.sim.autopilot

import pod.core.units.Location
import pod.core.vehicle.Severity
import pod.mavlink.command.CommandResult
import pod.mavlink.mission.MissionItem

/**
 * The geofence a ground station uploads (the FENCE list), enforced as the vehicle's profile picks
 * ([ArduPilotFence], [Px4Geofence]): the vehicle tests its position periodically and, on a new
 * breach while armed, says so and switches to its fence action's mode, once per breach.
 * [SimAutopilot.step] calls [step] after the physics, [SimAutopilot.setMode] calls [modeChanged],
 * and [Commands] asks the rest (DO_FENCE_ENABLE, guided destinations, arming, mode changes).
 */
internal abstract class Geofence(protected val ap: FlightControl) {
    private var source: List<MissionItem>? = null
    private var nextCheck = 0.0

    /** The zones of the FENCE list as the vehicle holds them. */
    protected var zones: FenceZones = FenceZones.NONE
        private set

    /** The current mode is the fence's doing (ArduPilot's ModeReason::FENCE_BREACHED). */
    protected var modeByFence = false
        private set

    /** The mode the fence switched away from. */
    protected var modeBeforeFence: String? = null
        private set

    /** Seconds between two checks of the position. */
    protected abstract val checkInterval: Double

    /** Tests the position against the fence and acts on what it finds. */
    protected abstract fun check()

    /** The zones of a newly loaded FENCE list that the vehicle keeps. */
    protected open fun accept(loaded: FenceZones): FenceZones = loaded

    /** Advances the fence by one simulation step. */
    open fun step() {
        refresh()
        // No origin, no fence: AC_PolyFence_loader loads only once the EKF has an origin, and PX4's
        // navigator skips the check without a valid global position.
        if (ap.time < nextCheck || !ap.positionReady) return
        nextCheck = ap.time + checkInterval
        check()
    }

    /** Any mode change, the fence's own included: from now on the mode is not the fence's doing. */
    open fun modeChanged() = forgetFenceMode()

    /** The current mode no longer counts as the fence's (ArduPlane's ModeReason::FENCE_REENABLE). */
    protected fun forgetFenceMode() {
        modeByFence = false
    }

    /** Switches to [name] as the fence's action. */
    protected fun setModeByFence(name: String) {
        val before = ap.modeName
        ap.setMode(name)
        modeByFence = true
        modeBeforeFence = before
    }

    /** Brings the zones up to date with the FENCE list (and the flavour's settings); cheap when nothing changed. */
    protected open fun refresh() {
        val items = ap.fenceItems
        if (items != source) {
            source = items
            zones = accept(FenceZones.of(items))
        }
    }

    /** MAV_CMD_DO_FENCE_ENABLE's result. */
    open fun enableCommand(cmd: CommandRequest): CommandResult = CommandResult.UNSUPPORTED

    /** Whether the vehicle would fly to [target] in guided flight (a DO_REPOSITION). */
    abstract fun allowsDestination(target: Location): Boolean

    /** Why the fence refuses arming now, or null. */
    open fun armingProblem(): String? = null

    /** The line refusing a change to mode [name] now, with its severity, or null when the fence allows it. */
    open fun refusesModeChange(name: String): Pair<String, Severity>? = null

    /** Height of [at] above home, m. */
    protected fun heightAboveHome(at: Location): Double = at.altitude.meters - ap.home.altitude.meters

    companion object {
        /** MAV_CMD_DO_FENCE_ENABLE. */
        const val DO_FENCE_ENABLE = 207
    }
}
