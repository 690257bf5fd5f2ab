package pod.mavlink.plan

import kotlin.math.atan2
import kotlin.math.cos
import kotlin.math.hypot
import kotlin.math.sin
import kotlin.math.tan
import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m

/**
 * Where a fixed-wing starts its final approach: a point [distanceFor] its height before the land
 * point, into the landing direction, so that the glide from it is [GLIDE_DEGREES].
 *
 * A plane cannot land from a waypoint over the land point: ArduPlane fixes its glide slope from the
 * previous waypoint's height and distance (AP_Landing::type_slope_setup_landing_glide_slope,
 * "Landing glide slope N degrees"), sinks no faster than TECS_SINK_MAX, flares early by
 * LAND_FLARE_SEC at that sink rate (type_slope_verify_land) and floats on past the point: on
 * ArduPlane 4.7 SITL a 53° slope flared at 52 m and touched down ~311 m past it. PX4 likewise
 * lands along the line from the previous waypoint (FixedwingPositionControl, FW_LND_ANG default 5°).
 */
public object LandingApproach {
    /** The glide from the approach point to the land point, in degrees below the horizon. */
    public const val GLIDE_DEGREES: Double = 5.0

    /** Height of the approach point above the land point when the plane is at least this high. */
    public val APPROACH_HEIGHT: Distance = 30.m

    /** Lowest approach point: below it the glide would be too short to settle on the line. */
    public val MIN_APPROACH_HEIGHT: Distance = 15.m

    /** How far before the land point an approach from [height] begins. */
    public fun distanceFor(height: Distance): Distance = (height.meters / tan(Math.toRadians(GLIDE_DEGREES))).m

    /**
     * The approach point (altitude above home) for landing at [land] when the plane comes from
     * [from] (altitude above home): into [heading] when given; else along the line from [from] to
     * the land point, or, when [from] is over the land point, along [lastCourse] (the bearing of
     * the plane's last leg, in degrees; north when unknown).
     */
    public fun point(land: Location, from: Location, heading: Angle?, lastCourse: Double?): Location {
        val height = from.altitude.coerceIn(MIN_APPROACH_HEIGHT, APPROACH_HEIGHT)
        val distance = distanceFor(height).meters
        val course = heading?.degrees ?: bearing(from, land)?.takeIf { distanceBetween(from, land) > OVERHEAD_M } ?: lastCourse ?: 0.0
        val back = Math.toRadians(course + 180.0)
        return land.copy(altitude = Distance.ZERO).offset(north = (distance * cos(back)).m, east = (distance * sin(back)).m).copy(altitude = height)
    }

    /** Bearing in degrees from [from] to [to], or null when they are the same point. */
    internal fun bearing(from: Location, to: Location): Double? {
        val (n, e) = northEast(from, to)
        return if (hypot(n, e) < 1e-6) null else (Math.toDegrees(atan2(e, n)) + 360.0) % 360.0
    }

    private fun distanceBetween(a: Location, b: Location): Double = northEast(a, b).let { (n, e) -> hypot(n, e) }

    private const val OVERHEAD_M = 10.0
}

/** Metres north and east from [from] to [to] (nearby points), through the same geodesy as [Location.offset]. */
internal fun northEast(from: Location, to: Location): Pair<Double, Double> {
    val probe = from.offset(north = PROBE_M.m, east = PROBE_M.m)
    val n = (to.latitude - from.latitude) / (probe.latitude - from.latitude) * PROBE_M
    val e = (to.longitude - from.longitude) / (probe.longitude - from.longitude) * PROBE_M
    return n to e
}

private const val PROBE_M = 1000.0
