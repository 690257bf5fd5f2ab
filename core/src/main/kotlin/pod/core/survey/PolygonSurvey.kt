package pod.core.survey

import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.deg
import kotlin.math.abs
import kotlin.math.ceil
import kotlin.math.cos
import kotlin.math.sin

/**
 * Plans surveys of any simple polygon, convex or concave: parallel tracks at a given angle, far
 * enough apart for the camera's side overlap, extended by a turnaround distance so that a plane
 * can turn outside the area.
 *
 * How the tracks are laid out:
 * - **Frame.** Work is done on a local flat frame: metres north and east of the polygon's first
 *   vertex ([Location.northEastTo], back with [Location.offset]), fine for areas of a few km.
 * - **Angle.** The track angle is the compass bearing of the tracks, clockwise from north: 0° makes
 *   them run north–south, 90° east–west (a track may be flown either way).
 * - **Tracks.** The polygon's width W across the tracks is cut into `n = ceil(W ÷ spacing)` strips
 *   one spacing wide, centred on it; a track runs along each strip's centre line. Every point of the
 *   polygon lies in some strip, so within half a spacing of that strip's centre line.
 * - **Track extent.** A track covers the polygon's whole along-track extent *within its strip*, not
 *   only where its centre line crosses the polygon: that is what puts every point of the polygon
 *   within half a spacing of a flown track (at a slanted edge the polygon is longer at the strip's
 *   edge than at its centre). The price: a track end may lie up to half a spacing outside the
 *   polygon, so waypoints lie within (turnaround + spacing ÷ 2) of it.
 * - **Concave polygons.** Within one strip the polygon may fall apart into several pieces along
 *   the track; each piece is a pass of its own (pieces whose extents overlap are flown as one).
 *   The passes are grouped into cells, regions that one back-and-forth pattern covers without
 *   leaving them (a boustrophedon cell decomposition: a new cell starts wherever the region splits
 *   around a notch or two branches join). Each cell is flown back and forth in one go, so the
 *   vehicle crosses a notch once per cell instead of once per strip; then it goes on to the
 *   nearest entry of an unflown cell (nearest in a straight line).
 * - **Transit legs.** A leg from one pass to the next is straight unless that would cut across
 *   the outside of a concave polygon; then it bends at polygon vertices, along the shortest path
 *   inside the polygon (waypoints marked [SurveyWaypoint.transit]). So not only every waypoint
 *   but every point of the flown path lies within (turnaround + spacing ÷ 2) of the polygon.
 * - **Entry.** A cell can be entered at four corners (its first or last pass, at either end); the
 *   first cell and corner are the ones whose first waypoint is nearest the start location.
 * - **Turnaround.** Each pass is extended by the turnaround distance before its start and after
 *   its end (waypoints marked [SurveyWaypoint.turnaround]; none when the distance is zero).
 *
 * Lengths: the photographed track length L satisfies `A ÷ s ≤ L ≤ A ÷ s + P`, A the area, s the
 * spacing and P the perimeter (the tests check it): each strip's pass is at least as long as the
 * polygon's chord anywhere in the strip, and longer only by what the edges inside the strip add.
 */
public object PolygonSurvey {
    /** Widths within this fraction above a whole number of spacings take no extra track (lat/lon rounding). */
    private const val STRIP_TOLERANCE: Double = 1e-9

    /** The smallest area, in square metres, that is planned; anything smaller is a degenerate polygon. */
    public const val MIN_AREA_SQUARE_METERS: Double = 1.0

    /** The most tracks one survey may have; a spacing that needs more is refused (a typo in units, usually). */
    public const val MAX_TRACKS: Int = 10_000

    /**
     * Plans a survey of [polygon] (≥ 3 vertices, not self-intersecting; a repeated closing vertex
     * is dropped) with waypoints at [height] above home, tracks at [trackAngle] (see the class
     * KDoc for the convention) spaced by [spacing], extended by [turnaround] at both ends, entered
     * at the corner nearest [start] (the first vertex when null), the camera fired as [trigger]
     * says. Invalid input throws [IllegalArgumentException] naming the problem.
     */
    public fun plan(
        polygon: List<Location>,
        height: Distance,
        spacing: SurveySpacing,
        trackAngle: Angle = 0.deg,
        turnaround: Distance = Distance.ZERO,
        start: Location? = null,
        trigger: CameraTrigger = CameraTrigger.DISTANCE,
    ): SurveyPlan {
        val vertices = if (polygon.size > 3 && polygon.first() == polygon.last()) polygon.dropLast(1) else polygon
        require(vertices.size >= 3) { "survey polygon needs at least 3 points, was ${vertices.size}" }
        requirePositive("survey height", height)
        require(turnaround.meters >= 0.0 && turnaround.meters.isFinite()) {
            "turnaround distance must be ≥ 0 and finite, was $turnaround"
        }
        require(trackAngle.degrees.isFinite()) { "track angle must be finite, was ${trackAngle.degrees}" }
        val camera = spacing as? SurveySpacing.FromCamera
        val footprint = camera?.camera?.footprint(camera.altitudeAboveGround)
        val (trackSpacing, triggerDistance) = when (spacing) {
            is SurveySpacing.Direct -> spacing.spacing to spacing.triggerDistance
            is SurveySpacing.FromCamera ->
                footprint!!.across * (1.0 - spacing.sideOverlap) to footprint.along * (1.0 - spacing.frontOverlap)
        }
        requirePositive("track spacing", trackSpacing)
        requirePositive("trigger distance", triggerDistance)

        val frame = TrackFrame(vertices.first(), trackAngle)
        val local = vertices.map(frame::toLocal)
        local.indices.firstOrNull { local[it] == local[(it + 1) % local.size] }?.let { i ->
            throw IllegalArgumentException(
                "survey polygon repeats a point: vertex $i and vertex ${(i + 1) % local.size} are the same",
            )
        }
        firstSelfIntersection(local)?.let { (i, j) ->
            val n = local.size
            throw IllegalArgumentException(
                "survey polygon is self-intersecting: edge $i (vertex $i → ${(i + 1) % n}) and " +
                    "edge $j (vertex $j → ${(j + 1) % n}) cross or overlap",
            )
        }
        val area = abs(signedArea(local))
        require(area >= MIN_AREA_SQUARE_METERS) {
            "survey polygon area ${area.formatArea()} m² is too small for one track (at least $MIN_AREA_SQUARE_METERS m²)"
        }

        val s = trackSpacing.meters
        val lowV = local.minOf { it.v }
        val width = local.maxOf { it.v } - lowV
        val strips = ceil(width / s * (1.0 - STRIP_TOLERANCE)).coerceAtLeast(1.0)
        require(strips <= MAX_TRACKS) {
            "track spacing ${trackSpacing.meters} m is too small for a polygon ${Distance(width)} wide: " +
                "${strips.toLong()} tracks (at most $MAX_TRACKS)"
        }
        val firstLine = lowV + (width - (strips - 1.0) * s) / 2.0
        val passes = (0 until strips.toInt()).map { strip ->
            val line = firstLine + strip * s
            // Shrunk by a hair so that an edge lying exactly on the border between two strips
            // (an L's inner edge at a whole number of spacings) does not stretch both strips' tracks.
            val half = s / 2.0 * (1.0 - STRIP_TOLERANCE)
            stripProjection(local, line - half, line + half).map { Pass(strip, line, it) }
        }
        val t = turnaround.meters
        val order = flightOrder(
            cells(passes),
            frame.toLocal(start ?: vertices.first()),
            entryPoint = { Point(if (it.fromHigh) it.pass.extent.end + t else it.pass.extent.start - t, it.pass.v) },
            exitPoint = { Point(if (it.fromHigh) it.pass.extent.start - t else it.pass.extent.end + t, it.pass.v) },
        )
        val path = TrackPath(t, triggerDistance.meters, trigger, TransitRouter(local))
        order.forEachIndexed { index, flown -> path.fly(index, flown) }

        return SurveyPlan(
            waypoints = path.points.map { (point, info) -> info.copy(location = frame.toLocation(point, height)) },
            spacing = trackSpacing,
            triggerDistance = triggerDistance,
            footprint = footprint,
            groundSamplingDistance = camera?.camera?.groundSamplingDistance(camera.altitudeAboveGround),
            trackCount = order.size,
            trackLength = Distance(order.sumOf { it.pass.extent.length }),
            totalLength = Distance(path.points.zipWithNext { a, b -> a.first.distanceTo(b.first) }.sum()),
            areaSquareMeters = area,
        )
    }

    private fun Double.formatArea(): String = (kotlin.math.round(this * 1000.0) / 1000.0).toString()
}

/** The local frame: u along the tracks, v across them (to their right), metres from [origin]. */
internal class TrackFrame(private val origin: Location, angle: Angle) {
    private val cosA = cos(angle.radians)
    private val sinA = sin(angle.radians)

    fun toLocal(location: Location): Point {
        val (north, east) = origin.northEastTo(location)
        return Point(north.meters * cosA + east.meters * sinA, -north.meters * sinA + east.meters * cosA)
    }

    fun toLocation(point: Point, height: Distance): Location {
        val north = point.u * cosA - point.v * sinA
        val east = point.u * sinA + point.v * cosA
        return origin.offset(Distance(north), Distance(east)).copy(altitude = height)
    }
}

/** Builds the waypoint list pass by pass, in the local frame. */
private class TrackPath(
    val turnaround: Double,
    val triggerDistance: Double,
    val trigger: CameraTrigger,
    val router: TransitRouter,
) {
    val points = ArrayList<Pair<Point, SurveyWaypoint>>()
    private val placeholder = Location(0.0, 0.0)

    fun fly(track: Int, flown: FlownPass) {
        val extent = flown.pass.extent
        val sign = if (flown.fromHigh) -1.0 else 1.0
        val from = if (flown.fromHigh) extent.end else extent.start
        val length = extent.length
        val v = flown.pass.v
        val entry = Point(from - sign * turnaround, v)
        points.lastOrNull()?.let { (exit, _) ->
            router.route(exit, entry).forEach { add(it, track, transit = true) }
        }
        if (turnaround > 0.0) add(entry, track, turnaround = true)
        val legs = when (trigger) {
            CameraTrigger.DISTANCE -> 1
            CameraTrigger.PER_WAYPOINT -> ceil(length / triggerDistance - 1e-9).toInt().coerceAtLeast(1)
        }
        for (leg in 0..legs) {
            val first = leg == 0
            val last = leg == legs
            add(
                Point(from + sign * length * leg / legs, v),
                track,
                trackStart = first,
                trackEnd = last,
                photo = trigger == CameraTrigger.PER_WAYPOINT || first,
            )
        }
        if (turnaround > 0.0) add(Point(from + sign * (length + turnaround), v), track, turnaround = true)
    }

    private fun add(
        point: Point,
        track: Int,
        trackStart: Boolean = false,
        trackEnd: Boolean = false,
        turnaround: Boolean = false,
        photo: Boolean = false,
        transit: Boolean = false,
    ) {
        points += point to SurveyWaypoint(placeholder, track, trackStart, trackEnd, turnaround, photo, transit)
    }
}
