package pod.core.queue

import pod.core.mission.SurveyDirection
import pod.core.units.Distance
import pod.core.units.Location

/**
 * A point a queued pattern flies to: metres north and east of the vehicle's home, as Paparazzi's
 * mission interface gives them, or a global position (Paparazzi's `_LLA` messages).
 */
public sealed interface QueuePoint {
    /**
     * [north] and [east] of the vehicle's home.
     *
     * @property north how far north of home; negative is south.
     * @property east how far east of home; negative is west.
     * @throws IllegalArgumentException when either is not finite or further than [MAX_OFFSET_M] from home.
     */
    public data class Local(val north: Distance, val east: Distance) : QueuePoint {
        init {
            require(north.meters.isFinite() && east.meters.isFinite()) { "a local point must be finite, was north $north, east $east" }
            require(kotlin.math.abs(north.meters) <= MAX_OFFSET_M && kotlin.math.abs(east.meters) <= MAX_OFFSET_M) {
                "a local point must lie within ${MAX_OFFSET_M / 1000} km of home, was north $north, east $east"
            }
        }

        override fun toString(): String = "(${north.meters.fmt()} N, ${east.meters.fmt()} E)"
    }

    /**
     * A latitude and longitude; the altitude of [location] is ignored (the element gives it).
     *
     * @property location the point; only its latitude and longitude count.
     * @throws IllegalArgumentException when the latitude or longitude is out of range.
     */
    public data class Global(val location: Location) : QueuePoint {
        init {
            require(location.latitude in -90.0..90.0 && location.longitude in -180.0..180.0) { "a global point needs a valid latitude and longitude, was $location" }
        }

        override fun toString(): String = "(${location.latitude}, ${location.longitude})"
    }

    /** The location of this point for a vehicle whose home is [home], at [height] above home. */
    public fun resolve(home: Location, height: Distance): Location = when (this) {
        is Local -> home.offset(north, east).copy(altitude = height)
        is Global -> location.copy(altitude = height)
    }

    /** The limit every [Local] point is checked against. */
    public companion object {
        /** How far from home a local point may lie (100 km): further is a typo, not a plan. */
        public const val MAX_OFFSET_M: Double = 100_000.0
    }
}

/** A point [north] and [east] of home: `at(30.m, -10.m)`. */
public fun at(north: Distance, east: Distance): QueuePoint = QueuePoint.Local(north, east)

/** A navigation pattern a [QueueElement] flies (Paparazzi's mission elements, and a few more). */
public sealed interface QueuePattern {
    /**
     * Fly to [point]; ends there.
     *
     * @property point where to fly.
     */
    public data class Goto(val point: QueuePoint) : QueuePattern

    /**
     * Circle [center] at [radius]: positive turns clockwise (seen from above), negative
     * counter-clockwise. Never ends by itself: give the element a duration or call `next()`.
     *
     * @property center the point circled.
     * @property radius the circle's radius, its sign the direction (positive: clockwise).
     * @throws IllegalArgumentException when [radius] is zero, not finite or beyond ±[MAX_RADIUS_M].
     */
    public data class Circle(val center: QueuePoint, val radius: Distance) : QueuePattern {
        init {
            require(radius.meters.isFinite() && radius.meters != 0.0) { "radius must be non-zero (its sign gives the direction), was $radius" }
            require(kotlin.math.abs(radius.meters) <= MAX_RADIUS_M) { "radius must be within ±${MAX_RADIUS_M.toInt()} m, was $radius" }
        }

        /** Whether it turns clockwise seen from above. */
        val clockwise: Boolean get() = radius.meters > 0
    }

    /**
     * Fly the segment from [from] to [to]: to [from] first, then along the line; ends at [to].
     *
     * @property from where the segment starts (flown to first).
     * @property to where it ends.
     */
    public data class Segment(val from: QueuePoint, val to: QueuePoint) : QueuePattern

    /**
     * Fly through [points] in order (a sequence of segments); ends at the last one.
     *
     * @property points the points, in the order flown.
     * @throws IllegalArgumentException when [points] is empty or longer than [MAX_PATH_POINTS].
     */
    public data class Path(val points: List<QueuePoint>) : QueuePattern {
        init {
            require(points.isNotEmpty()) { "a path needs at least one point" }
            require(points.size <= MAX_PATH_POINTS) { "a path takes at most $MAX_PATH_POINTS points, was ${points.size}" }
        }
    }

    /**
     * Survey the rectangle [length] × [width] that extends from [start] toward [direction] with
     * tracks at most [spacing] apart (a lawn mower, as `surveyArea` in missions); ends at its last
     * waypoint.
     *
     * @property start the corner the survey starts from.
     * @property length the rectangle's side along the tracks.
     * @property width the rectangle's side across the tracks.
     * @property spacing the largest distance between two tracks.
     * @property direction toward which corner the rectangle extends from [start].
     * @throws IllegalArgumentException when a side or the spacing is not positive and finite, or a side exceeds [MAX_SURVEY_SIDE_M].
     */
    public data class Survey(
        val start: QueuePoint,
        val length: Distance,
        val width: Distance,
        val spacing: Distance,
        val direction: SurveyDirection = SurveyDirection.NORTH_EAST,
    ) : QueuePattern {
        init {
            for ((name, value) in listOf("length" to length, "width" to width, "spacing" to spacing)) {
                require(value.meters > 0 && value.meters.isFinite()) { "survey $name must be positive and finite, was $value" }
            }
            require(length.meters <= MAX_SURVEY_SIDE_M && width.meters <= MAX_SURVEY_SIDE_M) { "survey sides must be at most ${MAX_SURVEY_SIDE_M / 1000} km" }
        }
    }

    /** Hold where the vehicle is when the element starts (a plane circles there). */
    public data object Hold : QueuePattern

    /** Land where the vehicle is; ends on the ground, disarmed. */
    public data object Land : QueuePattern

    /** Return to launch by the autopilot's own procedure; ends landed (a plane: circling home). */
    public data object ReturnHome : QueuePattern

    /** The limits patterns are checked against when they are made. */
    public companion object {
        /** The largest circle radius accepted (PX4's MC_ORBIT_RAD_MAX default is 1 km; planes go wider). */
        public const val MAX_RADIUS_M: Double = 10_000.0

        /** The most points a path takes (Paparazzi stops at 5; a mission can hold thousands). */
        public const val MAX_PATH_POINTS: Int = 1000

        /** The longest survey side accepted. */
        public const val MAX_SURVEY_SIDE_M: Double = 20_000.0
    }
}

private fun Double.fmt(): String = if (this == kotlin.math.floor(this)) toLong().toString() else toString()
