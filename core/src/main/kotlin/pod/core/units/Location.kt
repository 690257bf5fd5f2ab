package pod.core.units

import kotlin.math.asin
import kotlin.math.cos
import kotlin.math.sin
import kotlin.math.sqrt

/**
 * A point on the WGS-84 ellipsoid: latitude and longitude in degrees, [altitude] above mean sea
 * level.
 */
public data class Location(
    /** Latitude in degrees, -90..90. */
    public val latitude: Double,
    /** Longitude in degrees, -180..180. */
    public val longitude: Double,
    /** Altitude above mean sea level. */
    public val altitude: Distance = Distance.ZERO,
) {
    init {
        require(latitude in -90.0..90.0) { "latitude must be in -90..90, was $latitude" }
        require(longitude in -180.0..180.0) { "longitude must be in -180..180, was $longitude" }
    }

    /** Great-circle distance to [other] on a spherical Earth, ignoring altitude. */
    public fun distanceTo(other: Location): Distance {
        val dLat = (other.latitude - latitude).deg.radians
        val dLon = (other.longitude - longitude).deg.radians
        val a = sin(dLat / 2) * sin(dLat / 2) +
            cos(latitude.deg.radians) * cos(other.latitude.deg.radians) * sin(dLon / 2) * sin(dLon / 2)
        return Distance(2 * EARTH_RADIUS_M * asin(sqrt(a.coerceIn(0.0, 1.0))))
    }

    /** The point [north] and [east] of this one (flat-Earth offset, fine over a few kilometres), [up] higher. */
    public fun offset(north: Distance, east: Distance, up: Distance = Distance.ZERO): Location {
        val dLat = north.meters / EARTH_RADIUS_M * 180.0 / kotlin.math.PI
        val dLon = east.meters / (EARTH_RADIUS_M * cos(latitude.deg.radians)) * 180.0 / kotlin.math.PI
        return Location(latitude + dLat, longitude + dLon, altitude + up)
    }

    /**
     * How far [other] lies north and east of this location, on the local flat earth [offset] uses
     * (its inverse within millimetres over a few kilometres).
     */
    public fun northEastTo(other: Location): Pair<Distance, Distance> {
        val north = (other.latitude - latitude).deg.radians * EARTH_RADIUS_M
        val east = (other.longitude - longitude).deg.radians * EARTH_RADIUS_M * cos(latitude.deg.radians)
        return Distance(north) to Distance(east)
    }

    override fun toString(): String =
        "(${latitude.format(7)}, ${longitude.format(7)}, $altitude)"

    internal companion object {
        const val EARTH_RADIUS_M: Double = 6_371_008.8
    }
}
