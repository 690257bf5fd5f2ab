package pod.sim.autopilot

import pod.core.vehicle.Severity
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.MavFrames
import pod.mavlink.command.MavCommands.CONDITION_DELAY
import pod.mavlink.command.MavCommands.DO_CHANGE_SPEED
import pod.mavlink.command.MavCommands.DO_DIGICAM_CONTROL
import pod.mavlink.command.MavCommands.DO_JUMP
import pod.mavlink.command.MavCommands.DO_LAND_START
import pod.mavlink.command.MavCommands.DO_SET_CAM_TRIGG_DIST
import pod.mavlink.command.MavCommands.DO_SET_HOME
import pod.mavlink.command.MavCommands.IMAGE_START_CAPTURE
import pod.mavlink.command.MavCommands.IMAGE_STOP_CAPTURE
import pod.mavlink.command.MavCommands.NAV_CONTINUE_AND_CHANGE_ALT
import pod.mavlink.command.MavCommands.NAV_DELAY
import pod.mavlink.command.MavCommands.NAV_LAND
import pod.mavlink.command.MavCommands.NAV_LOITER_TIME
import pod.mavlink.command.MavCommands.NAV_LOITER_TO_ALT
import pod.mavlink.command.MavCommands.NAV_LOITER_TURNS
import pod.mavlink.command.MavCommands.NAV_LOITER_UNLIM
import pod.mavlink.command.MavCommands.NAV_RETURN_TO_LAUNCH
import pod.mavlink.command.MavCommands.NAV_SPLINE_WAYPOINT
import pod.mavlink.command.MavCommands.NAV_TAKEOFF
import pod.mavlink.command.MavCommands.NAV_VTOL_LAND
import pod.mavlink.command.MavCommands.NAV_VTOL_TAKEOFF
import pod.mavlink.command.MavCommands.NAV_WAYPOINT
import pod.mavlink.mission.MissionItem
import pod.sim.flight.Guidance

/**
 * Flies the MISSION list in AUTO: NAV items in order (with DO_JUMP), DO and CONDITION items as
 * they come (sequentially, as PX4 does; ArduPilot starts the DO items that follow a NAV item
 * together with it), MISSION_ITEM_REACHED when a NAV item completes, and the profile's behaviour
 * at the end. The list's form is the profile's too: ArduPilot's item 0 is home and is not flown
 * ([pod.sim.autopilot.profile.AutopilotProfile.firstMissionItem]). This class sequences the items;
 * [NavGuidance] flies each NAV item.
 *
 * The current item lives in the vehicle's mission server (MISSION_SET_CURRENT changes what is
 * flown next); a change made from outside while flying makes the runner jump there.
 */
internal class MissionRunner(private val ap: FlightControl) {
    private val profile get() = ap.profile
    private var seq = 0
    private var synced = -1
    private var done = false
    private val jumps = HashMap<Int, Int>()
    private var item = ItemProgress()
    private var holdAt: Location? = null
    private val nav = NavGuidance(ap, Leg())

    /** Where a paused mission holds (ArduCopter's DO_PAUSE_CONTINUE), or null when not paused. */
    var pausedAt: Location? = null
        private set

    /** True while the current item is a landing (NAV_LAND, or an RTL descending). */
    var landing = false
        private set

    /** True when the mission has ended with the vehicle on the ground. */
    var finishedOnGround = false
        private set

    private val items: List<MissionItem> get() = ap.missionItems
    private val first: Int get() = profile.firstMissionItem

    /** What [NavGuidance] sees of the item being flown and may change of the runner. */
    private inner class Leg : MissionLeg {
        override val items: List<MissionItem> get() = this@MissionRunner.items
        override val seq: Int get() = this@MissionRunner.seq
        override val first: Int get() = this@MissionRunner.first
        override val progress: ItemProgress get() = item
        override fun holdAt(at: Location?) {
            holdAt = at
        }
        override fun landing(now: Boolean) {
            landing = now
        }
        override fun location(item: MissionItem): Location = this@MissionRunner.location(item)
        override fun hold(): Guidance = this@MissionRunner.hold()
    }

    /**
     * ArduPilot's MISSION_RUNNING: not yet complete, or ended in a landing (a plane's NAV_LAND never
     * completes in AP_Landing::type_slope_verify_land; the mission runs until disarmed).
     */
    val running: Boolean get() = !done || finishedOnGround

    /** True when the list holds something AUTO can fly. */
    fun hasMission(): Boolean = items.size > first

    /** The index of the first DO_LAND_START marker, or null. */
    fun landStartIndex(): Int? = items.indexOfFirst { it.command == DO_LAND_START }.takeIf { it >= 0 }

    /** The first NAV command is a take-off (ArduCopter refuses AUTO on the ground without one). */
    fun startsWithTakeoff(): Boolean = items.drop(first).firstOrNull { it.command in NAV }?.command.let { it == NAV_TAKEOFF || it == NAV_VTOL_TAKEOFF }

    /** Starts or resumes: from the current item when it is a valid one, else from the first. */
    fun start() {
        val current = ap.missionCurrent
        if (done || current < first || current >= items.size) {
            seq = first
            jumps.clear()
        } else {
            seq = current
        }
        done = false
        finishedOnGround = false
        pausedAt = null
        newItem()
    }

    /** Starts at [index] (DO_LAND_START, MISSION_START with a first item). */
    fun startAt(index: Int) {
        done = false
        finishedOnGround = false
        seq = index.coerceAtLeast(first)
        jumps.clear()
        newItem()
    }

    /** Where the item being flown points (once it has been started), or null when paused or done. */
    val target: Location? get() = if (done || pausedAt != null) null else item.target

    /**
     * Starts the server's current item afresh, read from the list as it is now, with its target
     * resolved at once (ArduPilot's set_current_cmd while the mission runs; see
     * [SimAutopilot.onMissionMessage]). A finished mission stays finished.
     */
    fun restart() {
        if (done) return
        seq = ap.missionCurrent.coerceAtLeast(first)
        newItem()
        items.getOrNull(seq)?.takeIf { it.command in NAV }?.let { item.target = location(it) }
    }

    /** AUTO was left. */
    fun stop() {
        pausedAt = null
        landing = false
    }

    /** Pauses where the vehicle is; false when there is nothing to pause. */
    fun pause(): Boolean {
        if (done || !ap.flying) return false
        pausedAt = ap.body.location
        return true
    }

    /** Continues the paused item; false when not paused. */
    fun resume(): Boolean = (pausedAt != null).also { pausedAt = null }

    /** Whether the vehicle in AUTO on the ground is about to take off (so it is not parked). */
    fun wantsToFly(): Boolean = !done && (profile.autoTakesOffByItself || items.getOrNull(seq)?.command.let { it == NAV_TAKEOFF || it == NAV_VTOL_TAKEOFF })

    /**
     * A landing item touched down: it is complete. Where the profile says so
     * ([pod.sim.autopilot.profile.AutopilotProfile.disarmsAfterFinalLanding]) a mission ends this
     * way when no take-off follows the landing: it disarms at once, reports nothing reached, and
     * its mission goes back to the first item (ArduCopter/mode_auto.cpp, ModeAuto::verify_land
     * disarms and returns false, "leaves mission state machine in the current NAV_LAND";
     * ArduCopter/AP_Arming.cpp, AP_Arming_Copter::disarm calls mission.reset(), and
     * AP_Mission::update then starts item 1 again, "Mission: 1 Takeoff"). It stays in AUTO.
     */
    fun touchedDown() {
        landing = false
        if (profile.disarmsAfterFinalLanding && items.getOrNull(seq)?.command == NAV_LAND && !takeoffAfter(seq)) {
            ap.disarm()
            ap.text(Severity.INFO, "Disarming motors")
            seq = first
            newItem()
            ap.text(Severity.INFO, "Mission: $first ${commandName(items.getOrNull(first)?.command)}")
            done = true
            finishedOnGround = true
            holdAt = ap.body.location
            return
        }
        complete()
        if (seq >= items.size) finish()
    }

    /** A take-off follows NAV item [index] (ArduCopter then goes on after landing: AP_Mission::continue_after_land_check_for_takeoff). */
    private fun takeoffAfter(index: Int): Boolean =
        items.drop(index + 1).firstOrNull { it.command in NAV }?.command.let { it == NAV_TAKEOFF || it == NAV_VTOL_TAKEOFF }

    private fun commandName(command: Int?): String = when (command) {
        NAV_TAKEOFF -> "Takeoff"
        NAV_WAYPOINT -> "WP"
        else -> command?.toString() ?: "?"
    }

    /** What to fly this step. */
    fun guidance(): Guidance {
        if (ap.missionCurrent != synced) {
            seq = ap.missionCurrent.coerceAtLeast(first)
            done = false
            newItem()
        }
        pausedAt?.let { return Guidance.Loiter(it, 0.0) }
        repeat(MAX_ITEMS_PER_STEP) {
            if (done) return hold()
            val current = items.getOrNull(seq) ?: run {
                finish()
                return hold()
            }
            if (current.command in NAV) {
                nav.guidance(current)?.let { return it }
                complete()
            } else {
                if (doCommand(current)) return hold()
                advance()
            }
        }
        return hold()
    }

    private fun hold(): Guidance {
        val at = holdAt ?: ap.body.location
        if (ap.body.onGround) return Guidance.Idle
        // Airframe, not firmware: a multirotor hovers on the spot, a plane circles it.
        return if (profile.rotorcraft) Guidance.Loiter(at, 0.0) else ap.loiterRadius().let { (r, cw) -> Guidance.Loiter(at, r, cw) }
    }

    /** Runs DO / CONDITION item [it]; true while it still waits (CONDITION_DELAY). */
    private fun doCommand(it: MissionItem): Boolean {
        when (it.command) {
            CONDITION_DELAY -> {
                val until = item.waitUntil ?: (ap.time + it.param1).also { t -> item.waitUntil = t }
                return ap.time < until
            }
            DO_JUMP -> {
                val left = jumps.getOrPut(seq) { it.param2.toInt() }
                if (left != 0 && it.param1.toInt() in items.indices) {
                    if (left > 0) jumps[seq] = left - 1
                    seq = it.param1.toInt().coerceAtLeast(first) - 1 // advance() moves onto the target
                }
            }
            DO_CHANGE_SPEED -> ap.speeds.change(it.param1.toInt(), it.param2.toDouble())
            DO_SET_HOME -> ap.setHome(if (it.param1 == 1f || (it.x == 0 && it.y == 0)) ap.body.location else location(it))
            IMAGE_START_CAPTURE -> ap.camera.startInterval(it.param2.toDouble(), it.param3.toInt(), ap.time)
            IMAGE_STOP_CAPTURE -> ap.camera.stop()
            DO_DIGICAM_CONTROL -> if (it.x == 1) ap.camera.shoot(seq)
            DO_SET_CAM_TRIGG_DIST -> {
                ap.camera.startDistance(it.param1.toDouble())
                if (it.param3 == 1f) ap.camera.shoot(seq)
            }
            else -> Unit // DO_LAND_START is a marker; CONDITION_YAW and the rest change nothing simulated
        }
        return false
    }

    private fun complete() {
        ap.itemReached(seq)
        advance()
    }

    private fun advance() {
        seq++
        newItem()
    }

    private fun newItem() {
        item = ItemProgress()
        landing = false
        if (seq < items.size) {
            ap.setCurrent(seq)
        }
        synced = ap.missionCurrent
    }

    private fun finish() {
        if (done) return
        done = true
        landing = false
        holdAt = ap.body.location
        if (ap.body.onGround) {
            finishedOnGround = true
            return
        }
        profile.missionEndMode?.let { ap.setMode(it) }
    }

    /**
     * Where item [it] points, with its altitude resolved against home (terrain frames count as
     * relative), or the current altitude where the profile reads a zero altitude so
     * ([pod.sim.autopilot.profile.AutopilotProfile.zeroAltitudeMeansCurrent]).
     */
    private fun location(it: MissionItem): Location {
        val here = ap.body.location
        val base = if ((it.x == 0 && it.y == 0) || !it.isGlobal) here else Location(it.latitude, it.longitude)
        val alt = when {
            it.z == 0f && profile.zeroAltitudeMeansCurrent(it) -> here.altitude.meters
            it.frame == MavFrames.GLOBAL || it.frame == MavFrames.GLOBAL_INT -> it.z.toDouble()
            it.frame in RELATIVE_FRAMES -> ap.home.altitude.meters + it.z
            else -> here.altitude.meters
        }
        return base.copy(altitude = alt.m)
    }

    companion object {
        val NAV = setOf(
            NAV_WAYPOINT, NAV_LOITER_UNLIM, NAV_LOITER_TURNS, NAV_LOITER_TIME, NAV_RETURN_TO_LAUNCH, NAV_LAND, NAV_TAKEOFF,
            NAV_LOITER_TO_ALT, NAV_SPLINE_WAYPOINT, NAV_VTOL_TAKEOFF, NAV_VTOL_LAND, NAV_DELAY, NAV_CONTINUE_AND_CHANGE_ALT,
        )
        private const val MAX_ITEMS_PER_STEP = 64
        /** GLOBAL_RELATIVE_ALT, its _INT form and the terrain frames (flown here as relative). */
        private val RELATIVE_FRAMES = setOf(MavFrames.GLOBAL_RELATIVE_ALT, MavFrames.GLOBAL_RELATIVE_ALT_INT, MavFrames.GLOBAL_TERRAIN_ALT, MavFrames.GLOBAL_TERRAIN_ALT_INT)
    }
}
