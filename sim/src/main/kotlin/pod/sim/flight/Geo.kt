package pod.sim.flight

import pod.core.units.Location
import pod.core.units.m
import kotlin.math.atan2
import kotlin.math.hypot

/**
 * Metres north and east from [from] to [to] on the local flat Earth of core's [Location.northEastTo]
 * (the inverse of [Location.offset]), as the bare numbers the airframes integrate.
 */
internal fun northEast(from: Location, to: Location): Pair<Double, Double> =
    from.northEastTo(to).let { (north, east) -> north.meters to east.meters }

/** Horizontal distance in metres on the same flat Earth as [northEast]. */
internal fun horizontalDistance(from: Location, to: Location): Double = northEast(from, to).let { (n, e) -> hypot(n, e) }

/** Bearing in degrees 0..360 from [from] to [to]. */
internal fun bearing(from: Location, to: Location): Double = northEast(from, to).let { (n, e) -> wrap360(Math.toDegrees(atan2(e, n))) }

/** [location] moved [north] and [east] metres and [up] metres higher. */
internal fun moved(location: Location, north: Double, east: Double, up: Double): Location =
    location.offset(north = north.m, east = east.m, up = up.m)

/** [location] at altitude [amsl] metres. */
internal fun atAltitude(location: Location, amsl: Double): Location = location.copy(altitude = amsl.m)

/** [degrees] in 0..360. */
internal fun wrap360(degrees: Double): Double = ((degrees % 360.0) + 360.0) % 360.0

/** The signed smallest turn from [from] to [to] in degrees, -180..180. */
internal fun turn(from: Double, to: Double): Double {
    val d = wrap360(to - from)
    return if (d > 180) d - 360 else d
}
