package pod.sim.world

import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import pod.sim.flight.northEast
import kotlin.math.exp
import kotlin.math.sqrt
import kotlin.random.Random

/**
 * One smooth hill of a [Terrain]: a Gaussian bump [height] high at [north] / [east] of the
 * terrain's origin, its flanks falling to 61% of the height at [radius] (one standard deviation).
 */
public data class Hill(
    /** Metres north of the terrain's origin. */
    public val north: Distance,
    /** Metres east of the terrain's origin. */
    public val east: Distance,
    /** Height of the summit above the surrounding ground (negative: a hollow). */
    public val height: Distance,
    /** Width: one standard deviation of the bump. */
    public val radius: Distance,
) {
    init {
        require(radius.meters > 0) { "radius must be > 0, was $radius" }
    }
}

/**
 * The ground of a simulated flying area: [origin]'s altitude, a plane tilted by [slopeNorth] and
 * [slopeEast] (metres of rise per metre), and [hills] on it. Smooth everywhere, defined everywhere
 * (flat-Earth offsets from [origin], fine over a few kilometres), pure: the same terrain gives the
 * same elevation at the same place, so vehicles sharing one terrain fly over the same hills.
 */
public data class Terrain(
    /** Where the terrain is anchored; its altitude is the plane's elevation there. */
    public val origin: Location,
    /** The bumps on the plane. */
    public val hills: List<Hill> = emptyList(),
    /** Rise in metres per metre travelled north. */
    public val slopeNorth: Double = 0.0,
    /** Rise in metres per metre travelled east. */
    public val slopeEast: Double = 0.0,
) {
    init {
        require(slopeNorth.isFinite() && slopeEast.isFinite()) { "slopes must be finite, were $slopeNorth, $slopeEast" }
    }

    /** Elevation of the ground above mean sea level at [location] (its altitude is ignored). */
    public fun elevationAt(location: Location): Distance = elevationMetres(location).m

    /** [elevationAt] in metres, without boxing: the physics calls it every step. */
    internal fun elevationMetres(location: Location): Double {
        val (n, e) = northEast(origin, location)
        var z = origin.altitude.meters + slopeNorth * n + slopeEast * e
        for (hill in hills) {
            val dn = n - hill.north.meters
            val de = e - hill.east.meters
            val r = hill.radius.meters
            z += hill.height.meters * exp(-(dn * dn + de * de) / (2 * r * r))
        }
        return z
    }

    /** Makes terrains. */
    public companion object {
        /**
         * A seeded terrain around [origin]: [hillCount] hills up to [maxHillHeight] high, centred
         * within [extent] of the origin, each [extent]/10..[extent]/4 wide, on a plane that rises
         * at most [maxSlope] (metres per metre) in a seeded direction. The same seed gives the
         * same terrain.
         */
        public fun seeded(
            seed: Long,
            origin: Location,
            extent: Distance = 300.m,
            hillCount: Int = 4,
            maxHillHeight: Distance = 20.m,
            maxSlope: Double = 0.02,
        ): Terrain {
            require(extent.meters > 0) { "extent must be > 0, was $extent" }
            require(hillCount >= 0) { "hillCount must be ≥ 0, was $hillCount" }
            require(maxHillHeight.meters >= 0) { "maxHillHeight must be ≥ 0, was $maxHillHeight" }
            require(maxSlope in 0.0..1.0) { "maxSlope must be in 0..1, was $maxSlope" }
            val random = Random(seed)
            val size = extent.meters
            val hills = List(hillCount) {
                // Uniform over the disc of radius extent (the square root spreads them evenly).
                val d = size * sqrt(random.nextDouble())
                val a = random.nextDouble(0.0, 2 * Math.PI)
                Hill(
                    north = (d * kotlin.math.cos(a)).m,
                    east = (d * kotlin.math.sin(a)).m,
                    height = (maxHillHeight.meters * random.nextDouble(0.3, 1.0)).m,
                    radius = (size * random.nextDouble(0.1, 0.25)).m,
                )
            }
            val slope = maxSlope * random.nextDouble()
            val direction = random.nextDouble(0.0, 2 * Math.PI)
            return Terrain(origin, hills, slope * kotlin.math.cos(direction), slope * kotlin.math.sin(direction))
        }
    }
}
