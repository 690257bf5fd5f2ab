package pod.mavlink.executor

import kotlin.math.abs
import pod.core.mission.Mission
import pod.core.mission.MissionCompletion
import pod.core.mission.MissionStep
import pod.core.vehicle.Position
import pod.mavlink.plan.MissionFlavor

/** When a vehicle of one flavour counts as done with a mission: [Mission.completion], refined per airframe. */
internal object CompletionRules {
    /**
     * [Mission.completion], except that a fixed-wing mission ending in a return home is done once
     * the return item is reached: planes circle home instead of landing there.
     */
    fun rule(mission: Mission, flavor: MissionFlavor): MissionCompletion {
        val last = mission.steps.lastOrNull { it !is MissionStep.Action }
        return if (flavor.fixedWing && last == MissionStep.ReturnHome) MissionCompletion.LAST_STEP_DONE else mission.completion
    }

    /**
     * Whether [position] is within the circle of [loiter] (give or take a few metres), at its height:
     * ArduCopter hovers over the point whatever the radius, the simulator flies the circle. A plane circles at least its own loiter radius,
     * which Pod does not know, so any circle up to [PLANE_MAX_RADIUS_M] around the point counts.
     */
    fun loitering(loiter: MissionStep.Loiter, flavor: MissionFlavor, position: Position): Boolean {
        val d = position.location.distanceTo(loiter.location).meters
        val r = abs(loiter.radius.meters)
        val dz = abs(position.relativeAltitude.meters - loiter.location.altitude.meters)
        return if (flavor.fixedWing) {
            d <= maxOf(r, PLANE_MAX_RADIUS_M) * 1.25 && dz <= 10.0
        } else {
            d <= r + maxOf(3.0, r * 0.25) && dz <= 3.0
        }
    }

    /** Largest default loiter radius of the planes Pod knows (ArduPlane WP_LOITER_RAD, PX4 NAV_LOITER_RAD are 60–80 m). */
    const val PLANE_MAX_RADIUS_M = 100.0
}
