package pod.sim.autopilot

import pod.core.vehicle.Severity
import kotlin.math.abs
import kotlin.math.atan2
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.command.MavCommands.CONDITION_DELAY
import pod.mavlink.command.MavCommands.CONDITION_YAW
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
import pod.mavlink.mission.MissionType
import pod.sim.flight.Guidance
import pod.sim.flight.horizontalDistance
import pod.sim.flight.northEast

/**
 * Flies the MISSION list in AUTO: NAV items in order (with DO_JUMP), DO and CONDITION items as
 * they come (sequentially, as PX4 does; ArduPilot starts the DO items that follow a NAV item
 * together with it), MISSION_ITEM_REACHED when a NAV item completes, and the flavour's behaviour
 * at the end. ArduPilot's item 0 is home and is not flown; PX4 starts at item 0.
 *
 * The current item lives in the [SimAutopilot.missionServer] (MISSION_SET_CURRENT changes what
 * is flown next); a change made from outside while flying makes the runner jump there.
 */
internal class MissionRunner(private val ap: SimAutopilot) {
    private var seq = 0
    private var synced = -1
    private var done = false
    private val jumps = HashMap<Int, Int>()
    private var item = ItemState()
    private var holdAt: Location? = null

    /** Where a paused mission holds (ArduCopter's DO_PAUSE_CONTINUE), or null when not paused. */
    var pausedAt: Location? = null
        private set

    /** True while the current item is a landing (NAV_LAND, or an RTL descending). */
    var landing = false
        private set

    /** True when the mission has ended with the vehicle on the ground. */
    var finishedOnGround = false
        private set

    private class ItemState {
        var target: Location? = null
        var arrivedAt: Double? = null
        var circled = 0.0
        var lastBearing: Double? = null
        var waitUntil: Double? = null
        var plan: ReturnPlan? = null
        var approach: SlopeLanding? = null
        var legStart: Location? = null
    }

    private val items: List<MissionItem> get() = ap.missionServer.list(MissionType.MISSION)
    private val first: Int get() = if (ap.isPx4) 0 else 1

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
        val current = ap.missionServer.current
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
        seq = ap.missionServer.current.coerceAtLeast(first)
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
    fun wantsToFly(): Boolean = !done && (ap.isPx4 || items.getOrNull(seq)?.command.let { it == NAV_TAKEOFF || it == NAV_VTOL_TAKEOFF })

    /**
     * A landing item touched down: it is complete. ArduCopter ends a mission this way when no
     * take-off follows the landing: it disarms at once, reports nothing reached, and its mission
     * goes back to item 1 (ArduCopter/mode_auto.cpp, ModeAuto::verify_land disarms and returns
     * false, "leaves mission state machine in the current NAV_LAND"; ArduCopter/AP_Arming.cpp,
     * AP_Arming_Copter::disarm calls mission.reset(), and AP_Mission::update then starts item 1
     * again, "Mission: 1 Takeoff"). It stays in AUTO.
     */
    fun touchedDown() {
        landing = false
        if (ap.multirotor && !ap.isPx4 && items.getOrNull(seq)?.command == NAV_LAND && !takeoffAfter(seq)) {
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
        if (ap.missionServer.current != synced) {
            seq = ap.missionServer.current.coerceAtLeast(first)
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
                nav(current)?.let { return it }
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
        return if (ap.multirotor) Guidance.Loiter(at, 0.0) else ap.loiterRadius().let { (r, cw) -> Guidance.Loiter(at, r, cw) }
    }

    /** The guidance for NAV item [it], or null when it is complete. */
    private fun nav(it: MissionItem): Guidance? {
        val body = ap.body
        val target = item.target ?: location(it).also { t -> item.target = t }
        if (body.onGround && it.command != NAV_TAKEOFF && it.command != NAV_VTOL_TAKEOFF && it.command != NAV_LAND) {
            // PX4 takes off by itself before the first item; ArduPilot needs a take-off item.
            if (!ap.isPx4 || !ap.armed) return Guidance.Idle
            return Guidance.Climb(maxOf(target.altitude.meters, ap.takeoffAltitude(null)))
        }
        return when (it.command) {
            NAV_TAKEOFF, NAV_VTOL_TAKEOFF -> when {
                !ap.armed -> Guidance.Idle
                ap.takeoffReached(target.altitude.meters) -> null
                else -> Guidance.Climb(target.altitude.meters)
            }
            NAV_LAND, NAV_VTOL_LAND -> {
                landing = true
                holdAt = null
                if (!ap.isPx4 && !ap.multirotor) return slopeLanding(target)
                Guidance.Land(if (it.x == 0 && it.y == 0) (if (ap.multirotor) null else body.location) else target)
            }
            NAV_RETURN_TO_LAUNCH -> {
                val plan = item.plan ?: ap.returnPlan().also { p -> item.plan = p }
                val g = plan.guidance(body)
                landing = plan.landing
                if (plan.circlingHome) null else g
            }
            NAV_LOITER_UNLIM -> loiter(it, target)
            NAV_DELAY -> {
                val until = item.waitUntil ?: (ap.time + it.param1).also { t -> item.waitUntil = t }
                holdAt = target
                if (ap.time < until) hold() else null
            }
            NAV_CONTINUE_AND_CHANGE_ALT -> when {
                abs(body.location.altitude.meters - target.altitude.meters) < 2.0 -> null
                ap.multirotor -> Guidance.GoTo(target)
                else -> Guidance.Cruise(body.heading, target.altitude.meters)
            }
            NAV_LOITER_TIME -> loiter(it, target).takeIf { _ -> item.arrivedAt.let { a -> a == null || ap.time - a < it.param1 } }
            NAV_LOITER_TURNS -> turns(it, target)
            else -> waypoint(it, target)
        }
    }

    /** ArduPlane's NAV_LAND: the glide slope from the previous waypoint, flown by [SlopeLanding]. */
    private fun slopeLanding(target: Location): Guidance {
        val approach = item.approach ?: SlopeLanding(ap, previousWaypoint() ?: ap.body.location, target).also { a ->
            item.approach = a
            ap.text(Severity.INFO, String.format(java.util.Locale.ROOT, "Landing glide slope %.1f degrees", a.slopeDegrees))
        }
        return approach.guidance()
    }

    /** Where the NAV item before the current one pointed (what ArduPlane calls prev_WP_loc), or null. */
    private fun previousWaypoint(): Location? =
        (seq - 1 downTo first).asSequence().map { items[it] }.firstOrNull { it.command in NAV && (it.x != 0 || it.y != 0) }?.let { location(it) }

    private fun waypoint(it: MissionItem, target: Location): Guidance? {
        val body = ap.body
        if (item.arrivedAt == null) {
            val d = horizontalDistance(body.location, target)
            val radius = ap.acceptanceRadius(it.param2)
            val arrived = if (ap.multirotor) {
                d < radius && abs(body.location.altitude.meters - target.altitude.meters) < 1.0
            } else {
                // A plane also counts a waypoint whose finish line it has crossed: the line through the
                // waypoint square to the leg (ArduPlane verify_nav_wp, Location::past_interval_finish_line).
                d < radius || pastFinishLine(target)
            }
            if (!arrived) return Guidance.GoTo(target, through = if (ap.multirotor) throughSpeed(it, target) else 0.0, throughRadius = radius)
            item.arrivedAt = ap.time
            holdAt = target
        }
        val holdFor = if (ap.multirotor) it.param1.toDouble() else 0.0
        return if (ap.time - item.arrivedAt!! < holdFor) Guidance.Loiter(target, 0.0) else null
    }

    /**
     * How fast a multirotor flies through waypoint [it] at [target] on to the next, m/s; 0 when it
     * stops there. Neither autopilot stops at a waypoint without a hold time that another
     * positional item follows: ArduCopter gives the waypoint controller the next destination
     * (ArduCopter/mode_auto.cpp, ModeAuto::do_nav_wp → set_next_wp: not when p1 > 0, and only for a
     * next NAV_WAYPOINT, LOITER_UNLIM or LOITER_TIME; any other next command stops it), and PX4
     * plans a speed at the waypoint when a next position exists
     * (src/modules/flight_mode_manager/tasks/Auto, FlightTaskAutoLineSmoothVel::_getSpeedAtTarget),
     * which only a hold time takes away (src/modules/navigator/mission_block.cpp,
     * MissionBlock::get_time_inside counts param1 for a rotary wing's NAV_WAYPOINT). That speed is
     * PX4's corner limit √(a·r·tan(α/2)) (lib/mathlib/math/TrajMath.hpp, computeMaxSpeedInWaypoint,
     * with MPC_XY_TRAJ_P = 0.5 of the acceleration and the acceptance radius as r), capped by the
     * cruise speed and by stopping on the next leg; α is the angle at the waypoint, π on a straight
     * line, where it is the cruise speed. ArduCopter's S-curves round a corner by their own rule;
     * the same limit stands in for it (the bench flies straight lines).
     */
    private fun throughSpeed(it: MissionItem, target: Location): Double {
        if (it.param1 > 0f) return 0.0
        val next = items.drop(seq + 1).firstOrNull { n -> n.command in NAV } ?: return 0.0
        if (next.command !in THROUGH_TO || (next.x == 0 && next.y == 0)) return 0.0
        val after = location(next)
        val from = item.legStart ?: ap.body.location.also { l -> item.legStart = l }
        val (pn, pe) = northEast(target, from)
        val (nn, ne) = northEast(target, after)
        val legIn = kotlin.math.hypot(pn, pe)
        val legOut = kotlin.math.hypot(nn, ne)
        if (legOut < 1.0 || abs(after.altitude.meters - target.altitude.meters) > 1.0) return 0.0
        val perf = ap.performance()
        val cornerSpeed = if (legIn < 1.0) {
            perf.cruise
        } else {
            val alpha = kotlin.math.acos(((pn * nn + pe * ne) / (legIn * legOut)).coerceIn(-1.0, 1.0))
            kotlin.math.sqrt(0.5 * perf.acceleration * ap.acceptanceRadius(it.param2) * kotlin.math.tan(alpha / 2).coerceAtMost(1e6))
        }
        return minOf(perf.cruise, cornerSpeed, kotlin.math.sqrt(2 * perf.acceleration * 0.8 * legOut))
    }

    /** Whether the plane is past the line through [target] square to the leg from the previous waypoint. */
    private fun pastFinishLine(target: Location): Boolean {
        val from = item.legStart ?: (previousWaypoint() ?: ap.body.location).also { item.legStart = it }
        val (ln, le) = northEast(from, target)
        val length = kotlin.math.hypot(ln, le)
        if (length < 1.0) return false
        val (n, e) = northEast(from, ap.body.location)
        return (n * ln + e * le) / length >= length
    }

    private fun radiusOf(it: MissionItem): Pair<Double, Boolean> {
        val r = it.param3.toDouble()
        return when {
            // ArduPilot keeps no radius for NAV_LOITER_TIME, only the direction in param3's sign
            // (AP_Mission::mavlink_int_to_mission_cmd): the loiter radius parameter applies.
            it.command == NAV_LOITER_TIME && !ap.isPx4 -> ap.loiterRadius().let { (radius, cw) -> radius to (if (r != 0.0) r > 0 else cw) }
            r != 0.0 -> abs(r) to (r > 0)
            ap.multirotor -> 0.0 to true
            else -> ap.loiterRadius()
        }
    }

    private fun loiter(it: MissionItem, target: Location): Guidance {
        val (radius, cw) = radiusOf(it)
        holdAt = target
        if (item.arrivedAt == null && onCircle(target, radius)) item.arrivedAt = ap.time
        return Guidance.Loiter(target, radius, cw)
    }

    private fun turns(it: MissionItem, target: Location): Guidance? {
        var (radius, cw) = radiusOf(it)
        if (ap.multirotor && radius == 0.0) radius = ap.params["CIRCLE_RADIUS"] / 100 // the simulator does not pivot on the spot
        holdAt = target
        if (onCircle(target, radius)) {
            val (n, e) = northEast(target, ap.body.location)
            val bearing = Math.toDegrees(atan2(e, n))
            item.lastBearing?.let { last ->
                var delta = bearing - last
                if (delta > 180) delta -= 360
                if (delta < -180) delta += 360
                item.circled += if (cw) delta else -delta
            }
            item.lastBearing = bearing
        }
        return if (item.circled >= abs(it.param1) * 360.0) null else Guidance.Loiter(target, radius, cw)
    }

    private fun onCircle(center: Location, radius: Double): Boolean {
        val d = horizontalDistance(center, ap.body.location)
        return abs(d - radius) < maxOf(3.0, radius * 0.2) && abs(ap.body.location.altitude.meters - center.altitude.meters) < 5.0
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
            DO_CHANGE_SPEED -> ap.commands.changeSpeed(it.param1.toInt(), it.param2.toDouble())
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
        ap.reached += seq
        ap.emit(SimOutput.ItemReached(seq))
        advance()
    }

    private fun advance() {
        seq++
        newItem()
    }

    private fun newItem() {
        item = ItemState()
        landing = false
        if (seq < items.size) {
            ap.setCurrent(seq)
        }
        synced = ap.missionServer.current
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
        when {
            ap.isPx4 -> ap.setMode("AUTO.LOITER")
            !ap.multirotor -> ap.setMode("RTL")
            else -> Unit // ArduCopter holds at the last point, still in AUTO
        }
    }

    /**
     * Where item [it] points, with its altitude resolved against home (terrain frames count as
     * relative), or the current altitude where the autopilot reads a zero altitude so ([ItemAltitude]).
     */
    private fun location(it: MissionItem): Location {
        val here = ap.body.location
        val base = if ((it.x == 0 && it.y == 0) || !it.isGlobal) here else Location(it.latitude, it.longitude)
        val alt = when {
            ItemAltitude.meansCurrent(ap, it) -> here.altitude.meters
            it.frame == 0 || it.frame == 5 -> it.z.toDouble()
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
        private val RELATIVE_FRAMES = setOf(3, 6, 10, 11)
        /** The NAV items a multirotor flies a waypoint through to (ArduCopter's ModeAuto::set_next_wp). */
        private val THROUGH_TO = setOf(NAV_WAYPOINT, NAV_LOITER_UNLIM, NAV_LOITER_TIME)
    }
}
