package pod.core.mission

import pod.core.units.Distance
import pod.core.units.Location
import kotlin.math.ceil

/**
 * Toward which corner a survey rectangle extends from its start corner: `NORTH_EAST` means the
 * area lies north and east of the start.
 */
public enum class SurveyDirection(
    /** +1 when the tracks run north from the start corner, -1 when they run south. */
    public val northSign: Int,
    /** +1 when successive tracks step east, -1 when they step west. */
    public val eastSign: Int,
) {
    /** The area lies north and west of the start corner. */
    NORTH_WEST(1, -1),

    /** The area lies north and east of the start corner. */
    NORTH_EAST(1, 1),

    /** The area lies south and west of the start corner. */
    SOUTH_WEST(-1, -1),

    /** The area lies south and east of the start corner. */
    SOUTH_EAST(-1, 1),
}

/**
 * Plans lawn-mower (boustrophedon) surveys of a rectangle aligned with north.
 *
 * Geometry, drawn for `NORTH_EAST` (the other directions mirror it); waypoint 0 is the start corner:
 * ```
 *   north ▲   1 ───▶ 2     5 ──▶ 6
 *         │   ▲      │     ▲     │       length: along the tracks (north–south)
 *         │   │      ▼     │     ▼       width:  across the tracks (east–west)
 *         │   0      3 ──▶ 4     7
 *         └───┴──────┴─────┴─────┴──▶ east
 *             0   spacing  2·sp  width (the last gap is clipped)
 * ```
 * - Tracks run parallel to the north–south edges, `length` long; the first lies on the edge
 *   through the start corner, and each next one is `spacing` further across (east or west).
 * - There are `ceil(width / spacing) + 1` tracks ([trackCount]); the gap before the last track
 *   is clipped so that it lies exactly on the far edge (every gap is at most `spacing`).
 * - Each track contributes two waypoints (its two ends), so the vehicle flies back and forth and
 *   the crossings between tracks run along the north or south edge. The first waypoint is the
 *   start corner; the last one is on the far edge.
 * - Offsets use [Location.offset] from the start corner (flat Earth, fine for the 50 km the DSL
 *   allows away from the poles); every waypoint is at `height` above home.
 */
public object SurveyPlanner {
    /** Relative slack on `width / spacing` so that rounding noise does not add a needless last track. */
    private const val GAP_TOLERANCE: Double = 1e-9

    /**
     * How many tracks a survey [width] wide with tracks at most [spacing] apart has:
     * `ceil(width / spacing) + 1`, at least 2.
     */
    public fun trackCount(width: Distance, spacing: Distance): Int {
        requirePositive("width", width)
        requirePositive("spacing", spacing)
        return ceil(width.meters / spacing.meters - GAP_TOLERANCE).toInt().coerceAtLeast(1) + 1
    }

    /**
     * The waypoints of a lawn-mower survey of the rectangle [length] × [width] that extends from
     * [start] toward [direction], tracks at most [spacing] apart, all at [height] above home (the
     * altitude of [start] is ignored). Lengths must be positive and finite.
     */
    public fun lawnMower(
        start: Location,
        length: Distance,
        width: Distance,
        spacing: Distance,
        direction: SurveyDirection,
        height: Distance,
    ): List<Location> {
        requirePositive("length", length)
        val tracks = trackCount(width, spacing)
        val corner = start.copy(altitude = height)
        val northExtent = length * direction.northSign.toDouble()
        return buildList(tracks * 2) {
            for (track in 0 until tracks) {
                val across = if (track == tracks - 1) width else spacing * track.toDouble()
                val east = across * direction.eastSign.toDouble()
                val near = corner.offset(Distance.ZERO, east)
                val far = corner.offset(northExtent, east)
                if (track % 2 == 0) {
                    add(near)
                    add(far)
                } else {
                    add(far)
                    add(near)
                }
            }
        }
    }

    private fun requirePositive(name: String, value: Distance) {
        require(value.meters > 0.0 && value.meters.isFinite()) { "survey $name must be positive and finite, was $value" }
    }
}
