package pod.core.workflow

import pod.core.units.Location
import kotlin.math.hypot

/**
 * The order a backward pass visits the flagged waypoints in: short to fly, from where the forward
 * pass left the vehicle. A nearest-neighbour tour improved by 2-opt (reverse a stretch whenever
 * that shortens the route) until no reversal helps; an open route (it ends at the last waypoint,
 * the flight then returns home). Distances on the local flat earth, horizontal only.
 */
public object BackwardRoute {
    /** Indices into [waypoints] in flying order, starting from [start]; empty when nothing is flagged. */
    public fun order(start: Location, waypoints: List<Location>): List<Int> {
        if (waypoints.isEmpty()) return emptyList()
        val points = waypoints.map { start.northEastTo(it).let { (n, e) -> n.meters to e.meters } }
        val route = nearestNeighbour(points).toMutableList()
        improve(route, points)
        return route
    }

    /** The length (m) of flying [order] through [waypoints] from [start]. */
    public fun length(start: Location, waypoints: List<Location>, order: List<Int>): Double {
        val points = waypoints.map { start.northEastTo(it).let { (n, e) -> n.meters to e.meters } }
        return routeLength(order, points)
    }

    private fun nearestNeighbour(points: List<Pair<Double, Double>>): List<Int> {
        val left = points.indices.toMutableSet()
        var at = 0.0 to 0.0
        return buildList {
            while (left.isNotEmpty()) {
                val next = left.minWith(compareBy<Int> { distance(at, points[it]) }.thenBy { it })
                add(next)
                left -= next
                at = points[next]
            }
        }
    }

    /** 2-opt on an open route that starts at the origin: reverse `route[i..j]` while it shortens the route. */
    private fun improve(route: MutableList<Int>, points: List<Pair<Double, Double>>) {
        val origin = 0.0 to 0.0
        fun at(k: Int) = if (k < 0) origin else points[route[k]]
        var improved = true
        while (improved) {
            improved = false
            for (i in 0 until route.size - 1) {
                for (j in i + 1 until route.size) {
                    // Edges (i-1, i) and (j, j+1) become (i-1, j) and (i, j+1); an open end has no j+1.
                    val before = distance(at(i - 1), at(i)) + if (j + 1 < route.size) distance(at(j), at(j + 1)) else 0.0
                    val after = distance(at(i - 1), at(j)) + if (j + 1 < route.size) distance(at(i), at(j + 1)) else 0.0
                    if (after < before - EPSILON) {
                        route.subList(i, j + 1).reverse()
                        improved = true
                    }
                }
            }
        }
    }

    private fun routeLength(order: List<Int>, points: List<Pair<Double, Double>>): Double {
        var at = 0.0 to 0.0
        var total = 0.0
        for (i in order) {
            total += distance(at, points[i])
            at = points[i]
        }
        return total
    }

    private fun distance(a: Pair<Double, Double>, b: Pair<Double, Double>) = hypot(a.first - b.first, a.second - b.second)

    private const val EPSILON = 1e-9
}
