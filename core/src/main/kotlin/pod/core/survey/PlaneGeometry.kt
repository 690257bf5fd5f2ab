package pod.core.survey

import kotlin.math.hypot

/** A point of a local flat frame, in metres; the planner uses (along-track, across-track). */
internal data class Point(val u: Double, val v: Double) {
    operator fun minus(other: Point): Point = Point(u - other.u, v - other.v)

    fun distanceTo(other: Point): Double = hypot(u - other.u, v - other.v)
}

/** A closed interval [start, end] on one axis. */
internal data class Interval(val start: Double, val end: Double) {
    val length: Double get() = end - start

    fun overlaps(other: Interval): Boolean = start <= other.end && other.start <= end
}

internal fun cross(a: Point, b: Point): Double = a.u * b.v - a.v * b.u

/** Signed area (shoelace); positive when the vertices run counter-clockwise in (u, v). */
internal fun signedArea(polygon: List<Point>): Double {
    var sum = 0.0
    for (i in polygon.indices) {
        val a = polygon[i]
        val b = polygon[(i + 1) % polygon.size]
        sum += a.u * b.v - b.u * a.v
    }
    return sum / 2.0
}

internal fun perimeter(polygon: List<Point>): Double =
    polygon.indices.sumOf { polygon[it].distanceTo(polygon[(it + 1) % polygon.size]) }

/**
 * The first pair of edges that touch or cross where they should not, as edge indices (edge i runs
 * from vertex i to vertex i + 1), or null for a simple polygon. Neighbouring edges may only share
 * their common vertex: folding back along each other counts as an intersection.
 */
internal fun firstSelfIntersection(polygon: List<Point>): Pair<Int, Int>? {
    val n = polygon.size
    for (i in 0 until n) {
        val a = polygon[i]
        val b = polygon[(i + 1) % n]
        for (j in i + 1 until n) {
            val c = polygon[j]
            val d = polygon[(j + 1) % n]
            val adjacent = j == i + 1 || (i == 0 && j == n - 1)
            val hit = if (adjacent) foldsBack(a, b, c, d, j == i + 1) else segmentsTouch(a, b, c, d)
            if (hit) return i to j
        }
    }
    return null
}

/** Neighbouring edges a→b and c→d overlap beyond their shared vertex (collinear and turning back). */
private fun foldsBack(a: Point, b: Point, c: Point, d: Point, sharedIsB: Boolean): Boolean {
    // Shared vertex: b == c when the second edge follows the first, else d == a (wrap-around).
    val (shared, p, q) = if (sharedIsB) Triple(b, a, d) else Triple(a, b, c)
    val e1 = p - shared
    val e2 = q - shared
    if (e1.u == 0.0 && e1.v == 0.0 || e2.u == 0.0 && e2.v == 0.0) return true
    return cross(e1, e2) == 0.0 && e1.u * e2.u + e1.v * e2.v > 0.0
}

private fun orientation(a: Point, b: Point, c: Point): Int {
    val value = cross(b - a, c - a)
    return if (value > 0.0) 1 else if (value < 0.0) -1 else 0
}

private fun onSegment(a: Point, b: Point, p: Point): Boolean =
    p.u in minOf(a.u, b.u)..maxOf(a.u, b.u) && p.v in minOf(a.v, b.v)..maxOf(a.v, b.v)

/** Segments a–b and c–d share at least one point (crossing or touching). */
internal fun segmentsTouch(a: Point, b: Point, c: Point, d: Point): Boolean {
    val o1 = orientation(a, b, c)
    val o2 = orientation(a, b, d)
    val o3 = orientation(c, d, a)
    val o4 = orientation(c, d, b)
    if (o1 != o2 && o3 != o4) return true
    return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) ||
        (o3 == 0 && onSegment(c, d, a)) || (o4 == 0 && onSegment(c, d, b))
}

/**
 * The along-track (u) extent of the polygon inside the strip low ≤ v ≤ high, as disjoint sorted
 * intervals. The projection of a closed region equals the projection of its boundary, and the
 * boundary of polygon ∩ strip lies on the polygon's edges (clipped to the strip) and on the two
 * scan lines v = low and v = high (their inside intervals); so the union of those intervals,
 * merged, is the exact projection.
 */
internal fun stripProjection(polygon: List<Point>, low: Double, high: Double): List<Interval> {
    val pieces = ArrayList<Interval>()
    for (i in polygon.indices) {
        val a = polygon[i]
        val b = polygon[(i + 1) % polygon.size]
        clipToStrip(a, b, low, high)?.let(pieces::add)
    }
    pieces += scanLine(polygon, low)
    pieces += scanLine(polygon, high)
    return merge(pieces)
}

private fun clipToStrip(a: Point, b: Point, low: Double, high: Double): Interval? {
    val dv = b.v - a.v
    var t0 = 0.0
    var t1 = 1.0
    if (dv == 0.0) {
        if (a.v < low || a.v > high) return null
    } else {
        val tLow = (low - a.v) / dv
        val tHigh = (high - a.v) / dv
        t0 = maxOf(t0, minOf(tLow, tHigh))
        t1 = minOf(t1, maxOf(tLow, tHigh))
        if (t0 > t1) return null
    }
    val u0 = a.u + (b.u - a.u) * t0
    val u1 = a.u + (b.u - a.u) * t1
    return Interval(minOf(u0, u1), maxOf(u0, u1))
}

/** The inside intervals of the line v = [line] (even–odd rule, half-open at vertices). */
internal fun scanLine(polygon: List<Point>, line: Double): List<Interval> {
    val crossings = ArrayList<Double>()
    for (i in polygon.indices) {
        val a = polygon[i]
        val b = polygon[(i + 1) % polygon.size]
        if ((a.v > line) != (b.v > line)) crossings += a.u + (b.u - a.u) * (line - a.v) / (b.v - a.v)
    }
    crossings.sort()
    return crossings.chunked(2).filter { it.size == 2 }.map { Interval(it[0], it[1]) }
}

private fun merge(pieces: List<Interval>): List<Interval> {
    if (pieces.isEmpty()) return emptyList()
    val sorted = pieces.sortedBy { it.start }
    val merged = ArrayList<Interval>()
    var current = sorted.first()
    for (next in sorted.drop(1)) {
        current = if (next.start <= current.end) Interval(current.start, maxOf(current.end, next.end)) else {
            merged += current
            next
        }
    }
    merged += current
    return merged
}
