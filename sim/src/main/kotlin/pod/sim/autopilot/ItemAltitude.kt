package pod.sim.autopilot

import pod.mavlink.command.MavCommands.NAV_LOITER_TIME
import pod.mavlink.command.MavCommands.NAV_LOITER_TURNS
import pod.mavlink.command.MavCommands.NAV_LOITER_UNLIM
import pod.mavlink.command.MavCommands.NAV_SPLINE_WAYPOINT
import pod.mavlink.command.MavCommands.NAV_WAYPOINT
import pod.mavlink.mission.MissionItem

/**
 * What each autopilot makes of a mission item whose altitude is exactly zero. Not the same thing:
 * - ArduCopter fills in its current altitude for a NAV_WAYPOINT, spline or loiter item with z = 0,
 *   wherever the item points (ArduCopter/mode_auto.cpp, `ModeAuto::loc_from_cmd`: "use current
 *   altitude if not provided", called from `do_nav_wp` and `do_circle`; `do_loiter_unlimited` the
 *   same for LOITER_UNLIM and LOITER_TIME).
 * - ArduPlane does so only when latitude and longitude are zero too, a "loiter on the spot"
 *   (ArduPlane/commands.cpp, `Plane::set_next_WP`: "additionally treat zero altitude as current
 *   altitude" inside the lat == 0 && lng == 0 branch); a located item at 0 m is flown at 0 m.
 * - PX4 takes the altitude as given (src/modules/navigator/mission_block.cpp,
 *   `MissionBlock::get_absolute_altitude_for_item` adds home to a relative altitude, whatever it
 *   is), so a waypoint at 0 m above home is flown at ground level.
 */
internal object ItemAltitude {
    private val ARDUCOPTER_FILLS = setOf(NAV_WAYPOINT, NAV_SPLINE_WAYPOINT, NAV_LOITER_UNLIM, NAV_LOITER_TIME, NAV_LOITER_TURNS)

    /** True when [ap] flies [item] at its current altitude rather than at the item's. */
    fun meansCurrent(ap: SimAutopilot, item: MissionItem): Boolean {
        if (item.z != 0f || ap.isPx4) return false
        return if (ap.multirotor) item.command in ARDUCOPTER_FILLS else item.x == 0 && item.y == 0
    }
}
