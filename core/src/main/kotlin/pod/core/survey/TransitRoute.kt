package pod.core.survey

import kotlin.math.abs
import kotlin.math.hypot

/**
 * Routes the legs between passes so that they stay near the polygon: a leg from X (where a pass
 * ends) to Y (where the next begins), both within some distance r of the polygon, is flown
 * straight when the segment between their nearest polygon points p and q lies inside the polygon;
 * otherwise it bends at the polygon vertices of the shortest path from p to q inside the polygon.
 *
 * Why that keeps every point of the leg within r of the polygon: on a straight leg X→Y the point
 * at fraction λ is within (1 − λ)·|X − p| + λ·|Y − q| ≤ r of the point at λ on p→q, which is
 * inside the polygon; the same holds for X→(first vertex) against p→(first vertex), and the legs
 * between vertices are inside the polygon.
 */
internal class TransitRouter(private val polygon: List<Point>) {
    private val scale = polygon.maxOf { abs(it.u) + abs(it.v) } + 1.0
    private val tolerance = 1e-9 * scale
    private val visible = HashMap<Pair<Int, Int>, Boolean>()

    /** The polygon vertices to pass through between [from] and [to], empty for a straight leg. */
    fun route(from: Point, to: Point): List<Point> {
        val p = nearestPoint(from)
        val q = nearestPoint(to)
        if (insideSegment(p, q)) return emptyList()
        return shortestPath(p, q)
    }

    private fun nearestPoint(x: Point): Point {
        if (contains(x)) return x
        return polygon.indices.map { closestOnSegment(x, polygon[it], polygon[(it + 1) % polygon.size]) }
            .minBy { it.distanceTo(x) }
    }

    /** Dijkstra over the polygon's vertices; returns the vertices strictly between p and q. */
    private fun shortestPath(p: Point, q: Point): List<Point> {
        val n = polygon.size
        val sourceSees = BooleanArray(n) { insideSegment(p, polygon[it]) }
        val distance = DoubleArray(n) { if (sourceSees[it]) p.distanceTo(polygon[it]) else Double.POSITIVE_INFINITY }
        val previous = IntArray(n) { -1 }
        val done = BooleanArray(n)
        var best = if (insideSegment(p, q)) p.distanceTo(q) else Double.POSITIVE_INFINITY
        var last = -1
        while (true) {
            val i = (0 until n).filter { !done[it] && distance[it].isFinite() }.minByOrNull { distance[it] } ?: break
            if (distance[i] >= best) break
            done[i] = true
            if (insideSegment(polygon[i], q) && distance[i] + polygon[i].distanceTo(q) < best) {
                best = distance[i] + polygon[i].distanceTo(q)
                last = i
            }
            for (j in 0 until n) {
                if (done[j] || !sees(i, j)) continue
                val through = distance[i] + polygon[i].distanceTo(polygon[j])
                if (through < distance[j]) {
                    distance[j] = through
                    previous[j] = i
                }
            }
        }
        // A simple polygon is connected, so q is always reached; the fallback only guards rounding.
        return generateSequence(last.takeIf { it >= 0 }) { previous[it].takeIf { p -> p >= 0 } }
            .map { polygon[it] }.toList().asReversed()
    }

    private fun sees(i: Int, j: Int): Boolean =
        visible.getOrPut(minOf(i, j) to maxOf(i, j)) { insideSegment(polygon[i], polygon[j]) }

    /**
     * Segment a–b lies in the closed polygon: cut it wherever it meets an edge line or passes a
     * vertex, and every piece's midpoint must be inside or on the boundary.
     */
    private fun insideSegment(a: Point, b: Point): Boolean {
        val ab = b - a
        val cuts = arrayListOf(0.0, 1.0)
        for (i in polygon.indices) {
            val c = polygon[i]
            val cd = polygon[(i + 1) % polygon.size] - c
            val denominator = cross(ab, cd)
            if (abs(denominator) > 1e-12 * hypot(ab.u, ab.v) * hypot(cd.u, cd.v)) {
                val t = cross(c - a, cd) / denominator
                val s = cross(c - a, ab) / denominator
                if (t in 0.0..1.0 && s in -1e-9..1.0 + 1e-9) cuts += t
            }
            val lengthSquared = ab.u * ab.u + ab.v * ab.v
            if (lengthSquared > 0.0) cuts += (((c.u - a.u) * ab.u + (c.v - a.v) * ab.v) / lengthSquared).coerceIn(0.0, 1.0)
        }
        cuts.sort()
        return cuts.zipWithNext().all { (t0, t1) ->
            val t = (t0 + t1) / 2
            t1 - t0 < 1e-12 || insideOrOn(Point(a.u + ab.u * t, a.v + ab.v * t))
        }
    }

    private fun contains(p: Point): Boolean = scanLine(polygon, p.v).any { p.u >= it.start && p.u <= it.end }

    private fun insideOrOn(p: Point): Boolean = contains(p) ||
        polygon.indices.any { closestOnSegment(p, polygon[it], polygon[(it + 1) % polygon.size]).distanceTo(p) <= tolerance }
}

internal fun closestOnSegment(p: Point, a: Point, b: Point): Point {
    val ab = b - a
    val lengthSquared = ab.u * ab.u + ab.v * ab.v
    if (lengthSquared == 0.0) return a
    val t = (((p.u - a.u) * ab.u + (p.v - a.v) * ab.v) / lengthSquared).coerceIn(0.0, 1.0)
    return Point(a.u + ab.u * t, a.v + ab.v * t)
}
