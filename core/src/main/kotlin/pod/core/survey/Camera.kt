package pod.core.survey

import pod.core.units.Distance

/**
 * A survey camera pointing straight down: sensor size, focal length and image size in pixels.
 * The image's width (its [sensorWidth] side) lies across the tracks, its height along them, as
 * most planners mount the camera (landscape, long side across).
 */
public data class Camera(
    /** Sensor width, the side that lies across the tracks (13.2 mm for a 1" sensor). */
    public val sensorWidth: Distance,
    /** Sensor height, the side that lies along the tracks. */
    public val sensorHeight: Distance,
    /** Lens focal length. */
    public val focalLength: Distance,
    /** Image width in pixels (across the tracks). */
    public val imageWidth: Int,
    /** Image height in pixels (along the tracks). */
    public val imageHeight: Int,
) {
    init {
        requirePositive("camera sensor width", sensorWidth)
        requirePositive("camera sensor height", sensorHeight)
        requirePositive("camera focal length", focalLength)
        require(imageWidth > 0) { "camera image width must be ≥ 1 px, was $imageWidth" }
        require(imageHeight > 0) { "camera image height must be ≥ 1 px, was $imageHeight" }
    }

    /**
     * The ground one image covers from [altitude] above flat ground (similar triangles:
     * footprint = sensor size × altitude ÷ focal length).
     */
    public fun footprint(altitude: Distance): Footprint {
        requirePositive("altitude above ground", altitude)
        val scale = altitude.meters / focalLength.meters
        return Footprint(across = sensorWidth * scale, along = sensorHeight * scale)
    }

    /**
     * Ground sampling distance from [altitude]: the ground one pixel covers, the coarser of the
     * two image axes (`gsd.meters * 100` is the usual cm/px).
     */
    public fun groundSamplingDistance(altitude: Distance): Distance {
        val footprint = footprint(altitude)
        return Distance(maxOf(footprint.across.meters / imageWidth, footprint.along.meters / imageHeight))
    }
}

/** The ground an image covers: [across] the tracks and [along] them. */
public data class Footprint(
    /** Ground width across the tracks. */
    public val across: Distance,
    /** Ground length along the tracks. */
    public val along: Distance,
)

/**
 * How far apart the tracks are and how often the camera fires along them: given [Direct]ly, or
 * derived [FromCamera] and overlaps.
 */
public sealed interface SurveySpacing {
    /** Tracks [spacing] apart; the camera fires every [triggerDistance] along them. */
    public data class Direct(
        /** Distance between neighbouring tracks. */
        public val spacing: Distance,
        /** Distance between photos along a track; defaults to [spacing]. */
        public val triggerDistance: Distance = spacing,
    ) : SurveySpacing

    /**
     * Spacing from a [camera] at [altitudeAboveGround]: track spacing = footprint across ×
     * (1 − [sideOverlap]), trigger distance = footprint along × (1 − [frontOverlap]).
     */
    public data class FromCamera(
        /** The camera whose footprint the spacing is computed from. */
        public val camera: Camera,
        /** Height of the camera above the ground it photographs. */
        public val altitudeAboveGround: Distance,
        /** Overlap of consecutive photos along a track, a fraction in [0, 1). */
        public val frontOverlap: Double,
        /** Overlap of neighbouring tracks' photos, a fraction in [0, 1). */
        public val sideOverlap: Double,
    ) : SurveySpacing {
        init {
            requireOverlap("front overlap", frontOverlap)
            requireOverlap("side overlap", sideOverlap)
            requirePositive("altitude above ground", altitudeAboveGround)
        }
    }
}

private fun requireOverlap(name: String, value: Double) {
    require(value >= 0.0 && value < 1.0) { "$name must be in [0, 1), was $value" }
}

internal fun requirePositive(name: String, value: Distance) {
    require(value.meters > 0.0 && value.meters.isFinite()) { "$name must be positive and finite, was $value" }
}
