package pod.core.survey

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.units.mm
import kotlin.math.round

class PolygonSurveyTest : StringSpec({

    val origin = Location(41.178, -8.596)
    fun area(vararg northEast: Pair<Int, Int>): List<Location> = northEast.map { (n, e) -> origin.offset(n.m, e.m) }
    fun SurveyPlan.rounded(): List<Pair<Double, Double>> = locations.map { loc ->
        local(origin, loc).let { round(it.north * 1e6) / 1e6 to round(it.east * 1e6) / 1e6 }
    }
    val square = area(0 to 0, 0 to 100, 100 to 100, 100 to 0)

    "a 100 m square at 0° is flown as four north–south tracks on the strip centres, entered at the start corner" {
        val plan = PolygonSurvey.plan(square, 30.m, SurveySpacing.Direct(25.m), 0.deg)
        plan.rounded() shouldBe listOf(
            0.0 to 12.5, 100.0 to 12.5, 100.0 to 37.5, 0.0 to 37.5,
            0.0 to 62.5, 100.0 to 62.5, 100.0 to 87.5, 0.0 to 87.5,
        )
        plan.trackCount shouldBe 4
        plan.trackLength.meters shouldBe (400.0 plusOrMinus 1e-6)
        plan.totalLength.meters shouldBe (475.0 plusOrMinus 1e-6)
        plan.areaSquareMeters shouldBe (10_000.0 plusOrMinus 1e-3)
        plan.locations.forEach { it.altitude shouldBe 30.m }
        plan.waypoints.map { it.trackStart } shouldBe List(4) { listOf(true, false) }.flatten()
        plan.waypoints.map { it.trackEnd } shouldBe List(4) { listOf(false, true) }.flatten()
    }

    "a closing vertex that repeats the first one is dropped" {
        PolygonSurvey.plan(square + square.first(), 30.m, SurveySpacing.Direct(25.m)) shouldBe
            PolygonSurvey.plan(square, 30.m, SurveySpacing.Direct(25.m))
    }

    "at 90° the tracks run east–west, and the turnaround extends each one outside the square at both ends" {
        val plan = PolygonSurvey.plan(square, 30.m, SurveySpacing.Direct(50.m), 90.deg, turnaround = 10.m)
        plan.rounded() shouldBe listOf(
            25.0 to -10.0, 25.0 to 0.0, 25.0 to 100.0, 25.0 to 110.0,
            75.0 to 110.0, 75.0 to 100.0, 75.0 to 0.0, 75.0 to -10.0,
        )
        plan.waypoints.map { it.turnaround } shouldBe List(2) { listOf(true, false, false, true) }.flatten()
        plan.totalLength.meters shouldBe (2 * 120.0 + 50.0 plusOrMinus 1e-6)
    }

    "the entry is the corner nearest the start location, and the tracks are ordered from there" {
        val plan = PolygonSurvey.plan(square, 30.m, SurveySpacing.Direct(25.m), 0.deg, start = origin.offset(130.m, 120.m))
        plan.rounded().first() shouldBe (100.0 to 87.5)
        plan.rounded().last() shouldBe (100.0 to 12.5)
    }

    "an L-shaped area gets tracks as long as each arm, without stretching them over the inner corner" {
        val l = area(0 to 0, 0 to 100, 40 to 100, 40 to 40, 100 to 40, 100 to 0)
        val plan = PolygonSurvey.plan(l, 30.m, SurveySpacing.Direct(20.m), 0.deg)
        plan.rounded() shouldBe listOf(
            0.0 to 10.0, 100.0 to 10.0, 100.0 to 30.0, 0.0 to 30.0,
            0.0 to 50.0, 40.0 to 50.0, 40.0 to 70.0, 0.0 to 70.0, 0.0 to 90.0, 40.0 to 90.0,
        )
        plan.trackLength.meters shouldBe (plan.areaSquareMeters / 20.0 plusOrMinus 1e-6)
    }

    "a U-shaped area is flown arm by arm: each arm's tracks are consecutive, so the notch is crossed once" {
        // Base 0..40 m north across 0..120 m east; arms 40..100 m north at 0..40 and 80..120 east.
        val u = area(0 to 0, 0 to 120, 100 to 120, 100 to 80, 40 to 80, 40 to 40, 100 to 40, 100 to 0)
        val plan = PolygonSurvey.plan(u, 30.m, SurveySpacing.Direct(20.m), 90.deg)
        val armOfTrack = plan.waypoints.filter { it.trackStart }.map { wp ->
            val p = local(origin, wp.location)
            when {
                p.north < 40.0 -> "base"
                p.east < 60.0 -> "west"
                else -> "east"
            }
        }
        armOfTrack shouldBe List(2) { "base" } + List(3) { "west" } + List(3) { "east" }
    }

    "a leg that would cut across a U's notch bends at the notch's corner instead" {
        val u = area(0 to 0, 0 to 120, 100 to 120, 100 to 80, 40 to 80, 40 to 40, 100 to 40, 100 to 0)
        val plan = PolygonSurvey.plan(u, 30.m, SurveySpacing.Direct(20.m), 0.deg, start = origin.offset(100.m, 0.m))
        plan.rounded() shouldBe listOf(
            100.0 to 10.0, 0.0 to 10.0, 0.0 to 30.0, 100.0 to 30.0, 40.0 to 40.0,
            40.0 to 50.0, 0.0 to 50.0, 0.0 to 70.0, 40.0 to 70.0, 40.0 to 80.0,
            100.0 to 90.0, 0.0 to 90.0, 0.0 to 110.0, 100.0 to 110.0,
        )
        plan.waypoints.filter { it.transit }.map { it.track } shouldBe listOf(2, 4)
        plan.waypoints.none { it.transit && it.photo } shouldBe true
    }

    "photo per waypoint cuts each track into equal legs of at most the trigger distance" {
        val plan = PolygonSurvey.plan(
            square, 30.m, SurveySpacing.Direct(50.m, triggerDistance = 30.m), 0.deg,
            trigger = CameraTrigger.PER_WAYPOINT,
        )
        plan.rounded().take(5) shouldBe listOf(0.0 to 25.0, 25.0 to 25.0, 50.0 to 25.0, 75.0 to 25.0, 100.0 to 25.0)
        plan.waypoints.all { it.photo } shouldBe true
        plan.locations.size shouldBe 10
    }

    "the camera's footprint, GSD, spacing and trigger distance match the hand-computed values" {
        // 1" sensor 13.2 × 8.8 mm, 8.8 mm lens, 5472 × 3648 px at 100 m:
        // across = 13.2 × 100 / 8.8 = 150 m, along = 8.8 × 100 / 8.8 = 100 m,
        // GSD = 150 m / 5472 px = 100 m / 3648 px = 2.7412 cm/px,
        // spacing = 150 × (1 − 0.7) = 45 m, trigger = 100 × (1 − 0.8) = 20 m.
        val camera = Camera(13.2.mm, 8.8.mm, 8.8.mm, 5472, 3648)
        val plan = PolygonSurvey.plan(
            area(0 to 0, 0 to 400, 400 to 400, 400 to 0), 100.m,
            SurveySpacing.FromCamera(camera, 100.m, frontOverlap = 0.8, sideOverlap = 0.7),
        )
        plan.footprint!!.across.meters shouldBe (150.0 plusOrMinus 1e-9)
        plan.footprint!!.along.meters shouldBe (100.0 plusOrMinus 1e-9)
        plan.groundSamplingDistance!!.meters * 100 shouldBe (2.7412 plusOrMinus 1e-4)
        plan.spacing.meters shouldBe (45.0 plusOrMinus 1e-9)
        plan.triggerDistance.meters shouldBe (20.0 plusOrMinus 1e-9)
        plan.trackCount shouldBe 9 // ceil(400 / 45)
    }

    "invalid input fails at build time with a message naming the problem" {
        fun failure(block: () -> Unit): String = shouldThrow<IllegalArgumentException>(block).message!!
        val direct = SurveySpacing.Direct(10.m)
        failure { PolygonSurvey.plan(square.take(2), 30.m, direct) } shouldContain "at least 3 points"
        failure { PolygonSurvey.plan(area(0 to 0, 0 to 100, 100 to 0, 100 to 100), 30.m, direct) } shouldContain
            "self-intersecting: edge 1 (vertex 1 → 2) and edge 3 (vertex 3 → 0)"
        failure { PolygonSurvey.plan(square, 30.m, SurveySpacing.Direct(0.m)) } shouldContain "track spacing"
        failure { PolygonSurvey.plan(square, 30.m, SurveySpacing.Direct((-5).m)) } shouldContain "track spacing"
        failure { PolygonSurvey.plan(square, 30.m, SurveySpacing.Direct(Double.NaN.m)) } shouldContain "track spacing"
        failure { PolygonSurvey.plan(square, 30.m, SurveySpacing.Direct(10.m, 0.m)) } shouldContain "trigger distance"
        failure { PolygonSurvey.plan(square, 0.m, direct) } shouldContain "survey height"
        failure { PolygonSurvey.plan(square, 30.m, direct, turnaround = (-1).m) } shouldContain "turnaround"
        failure { PolygonSurvey.plan(area(0 to 0, 0 to 1, 1 to 0), 30.m, direct) } shouldContain "too small for one track"
        failure { PolygonSurvey.plan(area(0 to 0, 0 to 100, 0 to 100, 100 to 0), 30.m, direct) } shouldContain
            "repeats a point: vertex 1 and vertex 2"
        failure { PolygonSurvey.plan(square, 30.m, SurveySpacing.Direct(0.001.m)) } shouldContain
            "too small for a polygon 100.0 m wide: 100000 tracks (at most 10000)"
        val camera = Camera(13.2.mm, 8.8.mm, 8.8.mm, 5472, 3648)
        failure { SurveySpacing.FromCamera(camera, 100.m, frontOverlap = 1.0, sideOverlap = 0.5) } shouldContain "front overlap"
        failure { SurveySpacing.FromCamera(camera, 100.m, frontOverlap = 0.5, sideOverlap = -0.1) } shouldContain "side overlap"
        failure { SurveySpacing.FromCamera(camera, 0.m, frontOverlap = 0.5, sideOverlap = 0.5) } shouldContain "altitude"
    }
})
