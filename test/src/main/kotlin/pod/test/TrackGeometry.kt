package pod.test

import kotlin.math.atan2
import kotlin.math.hypot

// Plane geometry on a track's local frame (metres east as x, north as y), shared by the matchers.

/** Metres from ([north], [east]) to the segment [a]–[b] (north, east pairs in metres). */
internal fun offSegment(north: Double, east: Double, a: Pair<Double, Double>, b: Pair<Double, Double>): Double {
    val (an, ae) = a
    val ln = b.first - an
    val le = b.second - ae
    val length2 = ln * ln + le * le
    val t = if (length2 == 0.0) 0.0 else (((north - an) * ln + (east - ae) * le) / length2).coerceIn(0.0, 1.0)
    return hypot(north - (an + t * ln), east - (ae + t * le))
}

/**
 * Twice the signed area swept around [center] by [points] taken in order (north, east pairs):
 * positive counter-clockwise seen from above, negative clockwise.
 */
internal fun signedArea(points: List<Pair<Double, Double>>, center: Pair<Double, Double>): Double =
    points.zipWithNext().sumOf { (p, q) ->
        val x1 = p.second - center.second
        val y1 = p.first - center.first
        val x2 = q.second - center.second
        val y2 = q.first - center.first
        x1 * y2 - x2 * y1
    }

/** Degrees swept around [center] by [points] taken in order, counter-clockwise positive (each step taken the short way). */
internal fun degreesAround(points: List<Pair<Double, Double>>, center: Pair<Double, Double>): Double =
    points.zipWithNext().sumOf { (p, q) ->
        val from = atan2(p.first - center.first, p.second - center.second)
        val to = atan2(q.first - center.first, q.second - center.second)
        var d = Math.toDegrees(to - from)
        if (d > 180) d -= 360
        if (d < -180) d += 360
        d
    }

internal val TrackPoint.northEast: Pair<Double, Double> get() = north.meters to east.meters
