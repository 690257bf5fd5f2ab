package pod.sim.autopilot

import pod.core.units.Location
import pod.mavlink.command.MavCommands.NAV_LOITER_TIME
import pod.mavlink.command.MavCommands.NAV_LOITER_UNLIM
import pod.mavlink.command.MavCommands.NAV_WAYPOINT
import pod.mavlink.mission.MissionItem
import pod.sim.flight.northEast
import kotlin.math.abs

/**
 * How fast a multirotor flies through a mission waypoint on to the next, m/s; 0 when it stops
 * there. Neither autopilot stops at a waypoint without a hold time that another positional item
 * follows: ArduCopter gives the waypoint controller the next destination
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
internal object ThroughSpeed {
    /** The NAV items a multirotor flies a waypoint through to (ArduCopter's ModeAuto::set_next_wp). */
    private val THROUGH_TO = setOf(NAV_WAYPOINT, NAV_LOITER_UNLIM, NAV_LOITER_TIME)

    /** The speed through waypoint [it] at [target], the item [leg] flies now. */
    fun of(ap: FlightView, leg: MissionLeg, it: MissionItem, target: Location): Double {
        if (it.param1 > 0f) return 0.0
        val next = leg.items.drop(leg.seq + 1).firstOrNull { n -> n.command in MissionRunner.NAV } ?: return 0.0
        if (next.command !in THROUGH_TO || (next.x == 0 && next.y == 0)) return 0.0
        val after = leg.location(next)
        val item = leg.progress
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
}
