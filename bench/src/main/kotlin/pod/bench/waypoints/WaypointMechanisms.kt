package pod.bench.waypoints

import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.withTimeoutOrNull
import pod.bench.queue.QueueRig
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.MissionItem
import pod.mavlink.workflow.Stop
import pod.mavlink.workflow.WaypointFlight
import kotlin.math.hypot
import kotlin.math.roundToLong
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** How the vehicle is made to stop and hold at each waypoint while the action runs. */
enum class Mechanism(val label: String) {
    NONSTOP("no stops: AUTO mission, no hold time (reference path)"),
    QUEUE("(a) queue stop-and-go: WaypointFlight, a goto per waypoint"),
    GOTO_HOLD("(a′) a goto per waypoint, holding on the point it reached"),
    MODE_SWITCH("(b) AUTO; hold mode on MISSION_ITEM_REACHED, AUTO again after"),
    HOLD_SET_CURRENT("(c) AUTO, long hold time per waypoint; MISSION_SET_CURRENT after"),
}

/**
 * One flight of [count] waypoints [spacing] metres apart in a straight line from where the vehicle
 * is, northwards or ([north] false) southwards, at [height] above home, with an action lasting
 * [action] of vehicle time at every waypoint (none for [Mechanism.NONSTOP]).
 */
class WaypointCourse(
    private val rig: QueueRig,
    private val trace: Trace,
    private val flavour: Autopilot,
    val count: Int,
    val spacing: Double,
    val height: Double,
    val action: Duration,
    val north: Boolean,
) {
    private val px4 = flavour == Autopilot.PX4
    private val start: Location = rig.sim.state.value.location

    /** The waypoints, altitude above mean sea level. */
    val waypoints: List<Location> = (1..count).map { k ->
        start.offset(north = ((if (north) 1 else -1) * k * spacing).m, east = 0.m).copy(altitude = (rig.home.altitude.meters + height).m)
    }

    /** Flies [mechanism] and returns the actions run; the vehicle holds at the end. Bounded by [limit]. */
    suspend fun fly(mechanism: Mechanism, limit: Duration): List<ActionRun> = withTimeout(limit) {
        val actions = java.util.Collections.synchronizedList(ArrayList<ActionRun>())
        when (mechanism) {
            Mechanism.NONSTOP -> nonstop()
            Mechanism.QUEUE -> queue(actions)
            Mechanism.GOTO_HOLD -> gotoAndHold(actions)
            Mechanism.MODE_SWITCH -> modeSwitch(actions)
            Mechanism.HOLD_SET_CURRENT -> holdAndSetCurrent(actions)
        }
        actions.toList()
    }

    /** The bench's action: [action] of the vehicle's time at waypoint [index], logged. */
    private suspend fun act(index: Int, log: MutableList<ActionRun>) {
        val began = trace.now()
        trace.awaitTime(began + action.seconds())
        log += ActionRun(index, began, trace.now())
    }

    /**
     * The mission: ArduPilot's item 0 is home (not flown) and the waypoints follow from item 1;
     * PX4's start at item 0. Every waypoint gets hold time [hold] (param1, seconds), the last [lastHold].
     */
    private fun mission(hold: Float, lastHold: Float = hold): List<MissionItem> {
        val first = if (px4) 0 else 1
        val items = waypoints.mapIndexed { k, wp ->
            MissionItem(
                seq = first + k, frame = FRAME_GLOBAL_RELATIVE_ALT_INT, command = NAV_WAYPOINT, current = k == 0,
                param1 = if (k == waypoints.lastIndex) lastHold else hold,
                x = (wp.latitude * 1e7).roundToLong().toInt(), y = (wp.longitude * 1e7).roundToLong().toInt(), z = height.toFloat(),
            )
        }
        if (px4) return items
        val home = rig.home
        return listOf(MissionItem(seq = 0, frame = 0, command = NAV_WAYPOINT, x = (home.latitude * 1e7).roundToLong().toInt(), y = (home.longitude * 1e7).roundToLong().toInt(), z = home.altitude.meters.toFloat())) + items
    }

    private fun seq(k: Int): Int = if (px4) k else k + 1

    private val missionMode: String get() = if (px4) "AUTO.MISSION" else "AUTO"

    private suspend fun startMission(items: List<MissionItem>) {
        rig.vehicle.mission.upload(items)
        rig.vehicle.mission.setCurrent(seq(0))
        rig.vehicle.action.setMode(missionMode)
    }

    /**
     * The reference: the same waypoints as an AUTO mission with no hold time, flown through. The
     * last gets a hold time so that a PX4 flies onto it: the simulated PX4 ends a mission holding
     * where it is when the last item counts as reached, inside NAV_ACC_RAD (10 m) of it.
     */
    private suspend fun nonstop() {
        startMission(mission(hold = 0f, lastHold = LONG_HOLD_S))
        rig.sim.state.first { TimingAnalysis.distance(it.location, waypoints.last()) < TimingAnalysis.ARRIVAL_M }
    }

    /** (a) What Pod does today: [WaypointFlight], a goto per waypoint, stop, settle, act. */
    private suspend fun queue(log: MutableList<ActionRun>) {
        val relative = waypoints.map { it.copy(altitude = height.m) }
        WaypointFlight(rig.vehicle).fly(relative, Stop(timeout = 60.seconds) { visit -> act(visit.index, log) })
    }

    /**
     * (a′) As (a), but the vehicle is left holding on the goto's own point when it arrives: one
     * DO_REPOSITION per waypoint (`action.goto`), which both autopilots hold at once there
     * (ArduCopter GUIDED, PX4 Hold after a reposition). [WaypointFlight]'s queue instead sends a
     * new goto to where the ground last saw the vehicle when the queue runs empty (QueueFlight's
     * holdHere), a position up to one telemetry period and half a round trip old.
     */
    private suspend fun gotoAndHold(log: MutableList<ActionRun>) {
        for ((k, wp) in waypoints.withIndex()) {
            rig.vehicle.action.goto(wp)
            rig.vehicle.telemetry.position.first { p -> p != null && p.location.distanceTo(wp.copy(altitude = p.location.altitude)).meters < ARRIVAL_GROUND_M }
            settle()
            act(k, log)
        }
    }

    /**
     * (b) The mission flown in AUTO without hold times; on each MISSION_ITEM_REACHED the hold mode
     * (ArduCopter BRAKE, PX4 AUTO.LOITER: `action.hold()`), settle, act, then AUTO again, which
     * resumes at the current item: the next waypoint (ArduCopter ModeAuto::init sets
     * waiting_to_start and ModeAuto::run calls mission.start_or_resume(); PX4's mission resumes its
     * current item on activation).
     */
    private suspend fun modeSwitch(log: MutableList<ActionRun>) = coroutineScope {
        val reached = Channel<Int>(Channel.UNLIMITED)
        val listening = launch(start = CoroutineStart.UNDISPATCHED) { rig.vehicle.telemetry.itemReached.collect { reached.send(it) } }
        try {
            startMission(mission(hold = 0f))
            for (k in waypoints.indices) {
                while (reached.receive() != seq(k)) Unit
                rig.vehicle.action.hold()
                settle()
                act(k, log)
                if (k < waypoints.lastIndex) rig.vehicle.action.setMode(missionMode)
            }
        } finally {
            listening.cancel()
        }
    }

    /**
     * (c) The mission flown in AUTO with a long hold time at every waypoint (param1; both
     * autopilots stop and wait there: ArduCopter ModeAuto::verify_nav_wp, PX4
     * MissionBlock::get_time_inside for a rotary wing); the ground sees the vehicle stopped on the
     * waypoint in its telemetry, acts, and moves the mission on with `mission.setCurrent` to the
     * next item (MISSION_SET_CURRENT, which ArduPilot's AP_Mission::set_current_cmd starts at once).
     */
    private suspend fun holdAndSetCurrent(log: MutableList<ActionRun>) {
        startMission(mission(hold = LONG_HOLD_S))
        for (k in waypoints.indices) {
            rig.vehicle.telemetry.position.first { p -> p != null && p.location.distanceTo(waypoints[k].copy(altitude = p.location.altitude)).meters < ARRIVAL_GROUND_M }
            settle()
            act(k, log)
            if (k < waypoints.lastIndex) rig.vehicle.mission.setCurrent(seq(k + 1))
        }
    }

    /** As WaypointFlight: wait (at most 10 s) until the ground sees the vehicle slower than 0.3 m/s. */
    private suspend fun settle() {
        withTimeoutOrNull(10.seconds) {
            rig.vehicle.telemetry.position.first { p -> p != null && hypot(p.velocityNorth.metersPerSecond, p.velocityEast.metersPerSecond) < 0.3 }
        }
    }

    companion object {
        /** A hold time longer than any action: the vehicle waits until told to go on. */
        const val LONG_HOLD_S = 600f

        /** How close the ground must see the vehicle to a waypoint before it settles (QueueFlight's 2 m). */
        const val ARRIVAL_GROUND_M = 2.0
        private const val FRAME_GLOBAL_RELATIVE_ALT_INT = 6
        private const val NAV_WAYPOINT = 16
    }
}
