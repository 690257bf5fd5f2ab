package pod.core.workflow

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.doubles.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.pair
import io.kotest.property.checkAll
import pod.core.units.Location
import pod.core.units.m

class BackwardRouteTest : StringSpec({
    val start = Location(41.178, -8.596)
    fun at(n: Double, e: Double) = start.offset(n.m, e.m)

    "nothing flagged, no route" {
        BackwardRoute.order(start, emptyList()).shouldBeEmpty()
    }

    "points on a line are flown outward in order, whatever order they were flagged in" {
        val points = listOf(at(30.0, 0.0), at(10.0, 0.0), at(40.0, 0.0), at(20.0, 0.0))
        BackwardRoute.order(start, points) shouldBe listOf(1, 3, 0, 2)
    }

    val point = Arb.pair(Arb.double(-300.0, 300.0, includeNaNs = false), Arb.double(-300.0, 300.0, includeNaNs = false))

    // (Not "no longer than the flagged order": a local search can end above a lucky given order.)
    "every flagged waypoint is visited once, and the route is no longer than the nearest-neighbour one it starts from" {
        checkAll(PropTestConfig(iterations = 300, seed = 15), Arb.list(point, 1..25)) { raw ->
            val points = raw.map { (n, e) -> at(n, e) }
            val order = BackwardRoute.order(start, points)
            order.sorted() shouldBe points.indices.toList()
            val length = BackwardRoute.length(start, points, order)
            length shouldBeLessThanOrEqual nearestNeighbourLength(start, points) + 1e-6
        }
    }

    // 2-opt is a local search: on small routes it is within a few per cent of the best; 1.25 is a
    // bound a wrong reversal (or none) breaks on random instances.
    "on up to seven waypoints the route is within 25 % of the shortest one" {
        checkAll(PropTestConfig(iterations = 200, seed = 16), Arb.list(point, 1..7), Arb.int(0..0)) { raw, _ ->
            val points = raw.map { (n, e) -> at(n, e) }
            val best = permutations(points.indices.toList()).minOf { BackwardRoute.length(start, points, it) }
            BackwardRoute.length(start, points, BackwardRoute.order(start, points)) shouldBeLessThanOrEqual best * 1.25 + 1e-6
        }
    }
}) {
    private companion object {
        /** The nearest-neighbour route's length, on the same flat earth as BackwardRoute. */
        fun nearestNeighbourLength(start: Location, points: List<Location>): Double {
            val left = points.indices.toMutableList()
            var at = start
            val order = mutableListOf<Int>()
            while (left.isNotEmpty()) {
                val from = at
                val next = left.minBy { flat(from, points[it]) }
                order += next
                at = points[next]
                left.remove(next)
            }
            return BackwardRoute.length(start, points, order)
        }

        fun flat(a: Location, b: Location): Double = a.northEastTo(b).let { (n, e) -> kotlin.math.hypot(n.meters, e.meters) }

        fun permutations(items: List<Int>): List<List<Int>> =
            if (items.size <= 1) listOf(items) else items.flatMap { x -> permutations(items - x).map { listOf(x) + it } }
    }
}
