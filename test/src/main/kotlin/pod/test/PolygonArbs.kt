package pod.test

import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.sin
import kotlin.random.Random

/**
 * Simple polygons (never self-intersecting), convex and concave alike, around [center]: [corners]
 * vertices at [radius] from the centre, each at its own distance, in counter-clockwise order.
 * Each vertex lies in its own sector of the circle around the centre, so every polygon is
 * star-shaped about it: simple by construction, and concave wherever a vertex sits well inside its
 * neighbours. What `surveyWorkflow` and `PolygonSurvey.plan` take.
 */
public fun Arb.Companion.polygon(
    center: Location,
    radius: ClosedRange<Distance> = 30.m..120.m,
    corners: IntRange = 3..8,
): Arb<List<Location>> = polygons(center, radius, corners, convex = false)

/** Convex polygons around [center]: [corners] vertices on one circle of a radius drawn from [radius]. */
public fun Arb.Companion.convexPolygon(
    center: Location,
    radius: ClosedRange<Distance> = 30.m..120.m,
    corners: IntRange = 3..8,
): Arb<List<Location>> = polygons(center, radius, corners, convex = true)

private fun polygons(center: Location, radius: ClosedRange<Distance>, corners: IntRange, convex: Boolean): Arb<List<Location>> {
    require(radius.start.meters >= 1 && radius.endInclusive >= radius.start) { "radius must be a range from ≥ 1 m, was $radius" }
    require(!corners.isEmpty() && corners.first >= 3 && corners.last <= 100) { "corners must be within 3..100, was $corners" }
    return arbitrary { rs ->
        val random = rs.random
        val n = random.nextInt(corners.first, corners.last + 1)
        val onCircle = random.within(radius.start.meters..radius.endInclusive.meters)
        starShaped(random, n) { if (convex) onCircle else random.within(radius.start.meters..radius.endInclusive.meters) }
            .map { (north, east) -> center.offset(north.m, east.m) }
    }
}

/**
 * [n] points (north, east), counter-clockwise: the i-th at an angle inside the middle half of the
 * i-th of [n] equal sectors (so neighbours are never closer in angle than half a sector) and at the
 * distance [distance] draws.
 */
private fun starShaped(random: Random, n: Int, distance: () -> Double): List<Pair<Double, Double>> {
    val sector = 2 * PI / n
    val turn = random.nextDouble(0.0, 2 * PI)
    return List(n) { i ->
        val angle = turn + sector * (i + 0.25 + 0.5 * random.nextDouble())
        val r = distance()
        // Angles grow counter-clockwise seen from above: east is x, north is y.
        r * sin(angle) to r * cos(angle)
    }
}
