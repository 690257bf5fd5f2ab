package pod.core.mission

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.enum
import io.kotest.property.checkAll
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import kotlin.math.PI
import kotlin.math.abs
import kotlin.math.ceil
import kotlin.math.cos

class SurveyPlannerTest : StringSpec({

    val start = Location(41.178, -8.596)

    "a 100 m wide area with 50 m spacing has three tracks flown back and forth from the start corner" {
        val points = SurveyPlanner.lawnMower(start, 200.m, 100.m, 50.m, SurveyDirection.NORTH_EAST, 30.m)
        points.map { local(start, it) } shouldBe listOf(
            0.0 to 0.0, 200.0 to 0.0,
            200.0 to 50.0, 0.0 to 50.0,
            0.0 to 100.0, 200.0 to 100.0,
        ).map { (n, e) -> Local(n, e) }
        points.forEach { it.altitude shouldBe 30.m }
    }

    "the gap before the last track is clipped so that the last track lies on the far edge" {
        val points = SurveyPlanner.lawnMower(start, 80.m, 120.m, 50.m, SurveyDirection.NORTH_EAST, 10.m)
        points.map { local(start, it).east }.distinct() shouldBe listOf(0.0, 50.0, 100.0, 120.0)
    }

    "south-west surveys extend south and west of the start corner" {
        val points = SurveyPlanner.lawnMower(start, 60.m, 40.m, 40.m, SurveyDirection.SOUTH_WEST, 10.m)
        points.map { local(start, it) } shouldBe listOf(Local(0.0, 0.0), Local(-60.0, 0.0), Local(-60.0, -40.0), Local(0.0, -40.0))
    }

    "rounding noise in width / spacing does not add a needless track" {
        SurveyPlanner.trackCount(300.3.m, 100.1.m) shouldBe 4
        SurveyPlanner.trackCount(0.7.m, 0.1.m) shouldBe 8
    }

    "an area narrower than the spacing still gets its two edges flown" {
        SurveyPlanner.trackCount(5.m, 50.m) shouldBe 2
    }

    "non-positive or non-finite lengths are refused with the argument's name" {
        shouldThrow<IllegalArgumentException> {
            SurveyPlanner.lawnMower(start, 0.m, 10.m, 5.m, SurveyDirection.NORTH_EAST, 10.m)
        }.message!! shouldContain "length"
        shouldThrow<IllegalArgumentException> { SurveyPlanner.trackCount(Distance(Double.NaN), 5.m) }.message!! shouldContain "width"
        shouldThrow<IllegalArgumentException> { SurveyPlanner.trackCount(10.m, (-1).m) }.message!! shouldContain "spacing"
    }

    "every waypoint lies inside the rectangle, tracks are at most spacing apart and the last one is on the far edge" {
        checkAll(
            Arb.double(-70.0, 70.0, includeNaNs = false),
            Arb.double(-170.0, 170.0, includeNaNs = false),
            Arb.double(1.0, 5_000.0, includeNaNs = false),
            Arb.double(1.0, 5_000.0, includeNaNs = false),
            Arb.double(1.0, 1_000.0, includeNaNs = false),
            Arb.enum<SurveyDirection>(),
        ) { lat, lon, length, width, spacing, direction ->
            val corner = Location(lat, lon)
            val points = SurveyPlanner.lawnMower(corner, length.m, width.m, spacing.m, direction, 25.m)
            val tolerance = 1e-6 * (length + width)
            val tracks = ceil(width / spacing).toInt() + 1

            points shouldHaveSize tracks * 2
            points.first() shouldBe corner.copy(altitude = 25.m)
            val locals = points.map { local(corner, it) }
            locals.forEach { p ->
                p.north * direction.northSign shouldBe (length / 2 plusOrMinus length / 2 + tolerance)
                p.east * direction.eastSign shouldBe (width / 2 plusOrMinus width / 2 + tolerance)
            }
            points.forEach { it.altitude shouldBe 25.m }
            val across = locals.chunked(2).map { (a, b) ->
                a.east shouldBe (b.east plusOrMinus tolerance)
                abs(a.north - b.north) shouldBe (length plusOrMinus tolerance)
                abs(a.east)
            }
            across.zipWithNext { a, b -> b - a shouldBeLessThanOrEqual spacing + tolerance }
            across.last() shouldBe (width plusOrMinus tolerance)
        }
    }

    "consecutive tracks join along an edge, so the vehicle flies back and forth" {
        checkAll(
            Arb.double(1.0, 2_000.0, includeNaNs = false),
            Arb.double(1.0, 2_000.0, includeNaNs = false),
            Arb.double(1.0, 500.0, includeNaNs = false),
            Arb.enum<SurveyDirection>(),
        ) { length, width, spacing, direction ->
            val locals = SurveyPlanner.lawnMower(start, length.m, width.m, spacing.m, direction, 40.m).map { local(start, it) }
            val tolerance = 1e-6 * (length + width)
            locals.chunked(2).zipWithNext { previous, next ->
                next.first().north shouldBe (previous.last().north plusOrMinus tolerance)
            }
        }
    }
})

private data class Local(val north: Double, val east: Double)

/** Inverse of [Location.offset] from [origin]: the same flat-Earth scale, so the grid comes back exactly. */
private fun local(origin: Location, point: Location): Local {
    val metersPerDegree = Location.EARTH_RADIUS_M * PI / 180.0
    val north = (point.latitude - origin.latitude) * metersPerDegree
    val east = (point.longitude - origin.longitude) * metersPerDegree * cos(origin.latitude * PI / 180.0)
    return Local(round6(north), round6(east))
}

private fun round6(value: Double): Double = kotlin.math.round(value * 1e6) / 1e6
