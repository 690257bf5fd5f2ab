package pod.sim.autopilot

import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.mission.MissionItem
import pod.mavlink.plan.FenceCircle
import pod.mavlink.plan.FencePolygon
import pod.mavlink.plan.PlanListException
import pod.mavlink.plan.PlanLists
import pod.mavlink.plan.PlanPoint
import pod.sim.flight.horizontalDistance
import pod.sim.flight.northEast
import kotlin.math.hypot

/**
 * The zones of a vehicle's FENCE list (inclusion and exclusion polygons and circles) and its
 * breach return point, with the two tests both autopilots make: is a position inside a zone, and
 * how far is it from the zone's edge. Pure geometry, no flavour.
 */
internal class FenceZones private constructor(
    val zones: List<Zone>,
    /** MAV_CMD_NAV_FENCE_RETURN_POINT (5000), if the list holds one. */
    val returnPoint: PlanPoint?,
) {
    /** One inclusion or exclusion zone. */
    sealed interface Zone {
        val inclusion: Boolean

        /** True when [at] lies inside the zone (on its edge counts as either, as in both autopilots). */
        fun contains(at: Location): Boolean

        /** Metres from [at] to the zone's edge, whichever side it is on. */
        fun distanceToEdge(at: Location): Double
    }

    /**
     * A polygon tested on raw latitude and longitude with the crossing-number rule, as ArduPilot's
     * Polygon_outside (libraries/AP_Math/polygon.cpp) and PX4's Geofence::insidePolygon (PNPOLY,
     * src/modules/navigator/geofence.cpp) both do.
     */
    class Polygon(override val inclusion: Boolean, val vertices: List<PlanPoint>) : Zone {
        override fun contains(at: Location): Boolean {
            var inside = false
            var j = vertices.size - 1
            for (i in vertices.indices) {
                val a = vertices[i]
                val b = vertices[j]
                if ((a.longitude >= at.longitude) != (b.longitude >= at.longitude) &&
                    at.latitude <= (b.latitude - a.latitude) * (at.longitude - a.longitude) / (b.longitude - a.longitude) + a.latitude
                ) {
                    inside = !inside
                }
                j = i
            }
            return inside
        }

        override fun distanceToEdge(at: Location): Double {
            // On a flat Earth around the vehicle: metres north and east of it to each vertex.
            val points = vertices.map { northEast(at, Location(it.latitude, it.longitude, 0.m)) }
            return points.indices.minOf { i -> segmentDistance(points[i], points[(i + 1) % points.size]) }
        }

        private fun segmentDistance(a: Pair<Double, Double>, b: Pair<Double, Double>): Double {
            val (an, ae) = a
            val dn = b.first - an
            val de = b.second - ae
            val lengthSquared = dn * dn + de * de
            val t = if (lengthSquared == 0.0) 0.0 else (-(an * dn + ae * de) / lengthSquared).coerceIn(0.0, 1.0)
            return hypot(an + t * dn, ae + t * de)
        }
    }

    /**
     * A circle: inside when nearer its centre than its radius (ArduPilot's
     * AC_PolyFence_loader::breached compares Location::get_distance with the radius; PX4's
     * Geofence::insideCircle projects both points and compares squared distances).
     */
    class Circle(override val inclusion: Boolean, val center: PlanPoint, val radius: Double) : Zone {
        private fun distance(at: Location) = horizontalDistance(Location(center.latitude, center.longitude, 0.m), at)

        override fun contains(at: Location): Boolean = distance(at) < radius

        override fun distanceToEdge(at: Location): Double = kotlin.math.abs(distance(at) - radius)
    }

    /** True when there is no zone at all. */
    val isEmpty: Boolean get() = zones.isEmpty()

    /** The zones that [at] violates: inclusions it is outside of, exclusions it is inside. */
    fun violated(at: Location): List<Zone> = zones.filter { it.contains(at) != it.inclusion }

    /**
     * The first inclusion polygon's centre, as ArduPlane returns to when the list has no return
     * point: AC_PolyFence_loader::get_return_point falls back to calculate_centroid, the middle of
     * the polygon's latitude and longitude extent.
     */
    fun centroidOfFirstInclusion(): PlanPoint? = zones.filterIsInstance<Polygon>().firstOrNull { it.inclusion }?.vertices?.let { v ->
        PlanPoint((v.minOf { it.latitude } + v.maxOf { it.latitude }) / 2, (v.minOf { it.longitude } + v.maxOf { it.longitude }) / 2)
    }

    /** The same list with only the zones [keep] accepts (PX4 discards zones that fail its upload checks). */
    fun filter(keep: (Zone) -> Boolean): FenceZones = FenceZones(zones.filter(keep), returnPoint)

    companion object {
        /** MAV_CMD_NAV_FENCE_RETURN_POINT. */
        const val RETURN_POINT = 5000

        val NONE = FenceZones(emptyList(), null)

        /**
         * The zones of the FENCE list [items], read with [PlanLists.fence]. A list that describes no
         * fence (a polygon whose vertices do not add up) counts as none: the real vehicles refuse
         * such an upload, so a simulated one holding it has no fence to enforce.
         */
        fun of(items: List<MissionItem>): FenceZones {
            val returnPoint = items.firstOrNull { it.command == RETURN_POINT }?.let { PlanPoint(it.latitude, it.longitude) }
            val fence = try {
                PlanLists.fence(items.filter { it.command != RETURN_POINT })
            } catch (_: PlanListException) {
                return NONE
            }
            val polygons = fence.polygons.map { p: FencePolygon -> Polygon(p.inclusion, p.vertices) }
            val circles = fence.circles.map { c: FenceCircle -> Circle(c.inclusion, c.center, c.radiusMetres) }
            return FenceZones(polygons + circles, returnPoint)
        }
    }
}
