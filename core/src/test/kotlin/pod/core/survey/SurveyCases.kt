package pod.core.survey

import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.int
import pod.core.units.Location
import pod.core.units.m
import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.hypot
import kotlin.math.sin

/** North/east metres in the test's own flat frame (the polygon's first vertex, as the planner's). */
data class Ne(val north: Double, val east: Double) {
    fun distanceTo(other: Ne): Double = hypot(north - other.north, east - other.east)
}

/** A random survey: a star-shaped polygon (simple by construction) and the planner's other inputs. */
data class SurveyCase(
    val polygon: List<Location>,
    val convex: Boolean,
    val angleDegrees: Double,
    val spacing: Double,
    val turnaround: Double,
    val start: Location,
) {
    val origin: Location get() = polygon.first()
    val local: List<Ne> get() = polygon.map { local(origin, it) }

    fun plan(trigger: CameraTrigger = CameraTrigger.DISTANCE): SurveyPlan = PolygonSurvey.plan(
        polygon, 40.m, SurveySpacing.Direct(spacing.m), angleDegrees.let { pod.core.units.Angle(it) },
        turnaround.m, start, trigger,
    )
}

fun local(origin: Location, location: Location): Ne {
    val (north, east) = origin.northEastTo(location)
    return Ne(north.meters, east.meters)
}

/**
 * Vertices at sorted angles around a centre, each angular gap under π (weights 1..1.8 of a full
 * turn), radii random (concave) or all equal (convex): a star-shaped polygon, simple by
 * construction. Sizes 20 m – 2 km, spacings 2 %–80 % of the size.
 */
val surveyCases: Arb<SurveyCase> = arbitrary {
    val n = Arb.int(3..12).bind()
    val convex = Arb.boolean().bind()
    val size = Arb.double(20.0, 2_000.0, includeNaNs = false).bind()
    val weights = List(n) { Arb.double(1.0, 1.8, includeNaNs = false).bind() }
    val phase = Arb.double(0.0, 2 * PI, includeNaNs = false).bind()
    val centre = Location(
        Arb.double(-60.0, 60.0, includeNaNs = false).bind(),
        Arb.double(-170.0, 170.0, includeNaNs = false).bind(),
    )
    var angle = phase
    val polygon = weights.map { weight ->
        val radius = if (convex) size else size * Arb.double(0.15, 1.0, includeNaNs = false).bind()
        val vertex = centre.offset((radius * cos(angle)).m, (radius * sin(angle)).m)
        angle += 2 * PI * weight / weights.sum()
        vertex
    }
    val start = centre.offset(
        Arb.double(-3 * size, 3 * size, includeNaNs = false).bind().m,
        Arb.double(-3 * size, 3 * size, includeNaNs = false).bind().m,
    )
    SurveyCase(
        polygon = polygon,
        convex = convex,
        angleDegrees = Arb.double(-360.0, 360.0, includeNaNs = false).bind(),
        spacing = size * Arb.double(0.02, 0.8, includeNaNs = false).bind(),
        turnaround = if (Arb.boolean().bind()) 0.0 else Arb.double(0.0, 100.0, includeNaNs = false).bind(),
        start = start,
    )
}

fun shoelaceArea(polygon: List<Ne>): Double {
    var twice = 0.0
    polygon.forEachIndexed { i, a ->
        val b = polygon[(i + 1) % polygon.size]
        twice += a.east * b.north - b.east * a.north
    }
    return kotlin.math.abs(twice) / 2
}

fun edges(polygon: List<Ne>): List<Pair<Ne, Ne>> = polygon.indices.map { polygon[it] to polygon[(it + 1) % polygon.size] }

/** Winding-number test (independent of the planner's even–odd scan lines). */
fun inside(polygon: List<Ne>, p: Ne): Boolean {
    var winding = 0
    for ((a, b) in edges(polygon)) {
        val side = (b.east - a.east) * (p.north - a.north) - (p.east - a.east) * (b.north - a.north)
        if (a.north <= p.north) {
            if (b.north > p.north && side > 0) winding++
        } else if (b.north <= p.north && side < 0) {
            winding--
        }
    }
    return winding != 0
}

fun distanceToSegment(p: Ne, a: Ne, b: Ne): Double {
    val dn = b.north - a.north
    val de = b.east - a.east
    val lengthSquared = dn * dn + de * de
    if (lengthSquared == 0.0) return p.distanceTo(a)
    val t = (((p.north - a.north) * dn + (p.east - a.east) * de) / lengthSquared).coerceIn(0.0, 1.0)
    return p.distanceTo(Ne(a.north + dn * t, a.east + de * t))
}

/** How far [p] lies outside the polygon: 0 inside or on it. */
fun distanceOutside(polygon: List<Ne>, p: Ne): Double =
    if (inside(polygon, p)) 0.0 else edges(polygon).minOf { (a, b) -> distanceToSegment(p, a, b) }

/** The photographed segment of each track, start to end, in the test frame. */
fun trackSegments(plan: SurveyPlan, origin: Location): List<Pair<Ne, Ne>> =
    plan.waypoints.groupBy { it.track }.values.map { points ->
        local(origin, points.first { it.trackStart }.location) to local(origin, points.last { it.trackEnd }.location)
    }
