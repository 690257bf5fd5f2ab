package pod.mavlink.executor

import kotlin.math.abs
import pod.core.mission.Mission
import pod.core.mission.MissionCompletion
import pod.core.mission.MissionStep
import pod.core.vehicle.Position
import pod.mavlink.plan.MissionFlavor
import pod.mavlink.plan.northEast

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
     * Whether a multirotor at [position] is within the circle of [loiter] (give or take a few
     * metres), at its height: ArduCopter hovers over the point whatever the radius, the simulator
     * flies the circle. Planes are judged by [CircleWatch].
     */
    fun loitering(loiter: MissionStep.Loiter, flavor: MissionFlavor, position: Position): Boolean {
        val d = position.location.distanceTo(loiter.location).meters
        val r = abs(loiter.radius.meters)
        val dz = abs(position.relativeAltitude.meters - loiter.location.altitude.meters)
        return d <= r + maxOf(3.0, r * 0.25) && dz <= 3.0
    }

    /** Largest default loiter radius of the planes Pod knows (ArduPlane WP_LOITER_RAD, PX4 NAV_LOITER_RAD are 60–80 m). */
    const val PLANE_MAX_RADIUS_M = 100.0
}

/**
 * Whether a plane is established on the circle of [loiter]: an unlimited loiter is never reported
 * reached (ArduPlane's Plane::verify_loiter_unlim always returns false, commands_logic.cpp), and a
 * plane on its way passes within any "near enough" distance of the centre long before it circles. So it counts as established once, near the centre (within
 * the item's radius or its own loiter radius, at most [CompletionRules.PLANE_MAX_RADIUS_M], with
 * a margin) and at the loiter's height, it has flown [ARC_DEGREES] around the centre moving along
 * the circle (little of its speed towards or away from the centre). Feed it every position while
 * the loiter is the current item.
 */
internal class CircleWatch(private val loiter: MissionStep.Loiter) {
    private var lastBearing: Double? = null
    private var swept = 0.0

    /** Whether the plane, now at [position], is established on the circle. */
    fun established(position: Position): Boolean {
        val center = loiter.location
        val (north, east) = northEast(center, position.location)
        val d = kotlin.math.hypot(north, east)
        val maxRadius = maxOf(abs(loiter.radius.meters), CompletionRules.PLANE_MAX_RADIUS_M) * 1.25
        val dz = abs(position.relativeAltitude.meters - center.altitude.meters)
        val vn = position.velocityNorth.metersPerSecond
        val ve = position.velocityEast.metersPerSecond
        val speed = kotlin.math.hypot(vn, ve)
        val radial = if (d > 0) abs(vn * north + ve * east) / d else speed
        if (d < MIN_RADIUS_M || d > maxRadius || dz > 10.0 || speed < 1.0 || radial > speed * MAX_RADIAL_SHARE) {
            lastBearing = null
            swept = 0.0
            return false
        }
        val bearing = Math.toDegrees(kotlin.math.atan2(east, north))
        lastBearing?.let { last -> swept += ((bearing - last + 540.0) % 360.0) - 180.0 }
        lastBearing = bearing
        return abs(swept) >= ARC_DEGREES
    }

    private companion object {
        const val ARC_DEGREES = 90.0
        const val MAX_RADIAL_SHARE = 0.35
        const val MIN_RADIUS_M = 10.0
    }
}
