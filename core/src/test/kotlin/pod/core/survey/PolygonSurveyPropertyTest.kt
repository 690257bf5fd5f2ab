package pod.core.survey

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThanOrEqual
import io.kotest.matchers.doubles.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.filter
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll
import pod.core.units.m
import pod.core.units.mm
import kotlin.math.PI
import kotlin.math.abs
import kotlin.math.cos
import kotlin.math.sin

class PolygonSurveyPropertyTest : StringSpec({

    val config = PropTestConfig(iterations = 300, seed = 20261125)

    /** Slack for the lat/lon round trip and floating point: a micrometre per metre of size. */
    fun SurveyCase.epsilon(): Double = 1e-6 * (1.0 + local.maxOf { abs(it.north) + abs(it.east) })

    "full coverage: every sampled point of the polygon, inside or on the edge, is within half a spacing of a track" {
        checkAll(config, surveyCases) { case ->
            val plan = case.plan()
            val polygon = case.local
            val tracks = trackSegments(plan, case.origin)
            val north = polygon.minOf { it.north }..polygon.maxOf { it.north }
            val east = polygon.minOf { it.east }..polygon.maxOf { it.east }
            val grid = (0..30).flatMap { i ->
                (0..30).map { j ->
                    Ne(north.start + (north.endInclusive - north.start) * i / 30, east.start + (east.endInclusive - east.start) * j / 30)
                }
            }.filter { inside(polygon, it) }
            val boundary = edges(polygon).flatMap { (a, b) ->
                (0..20).map { k -> Ne(a.north + (b.north - a.north) * k / 20, a.east + (b.east - a.east) * k / 20) }
            }
            for (p in grid + boundary) {
                val nearest = tracks.minOf { (a, b) -> distanceToSegment(p, a, b) }
                withClue("$case: point $p is $nearest m from the nearest track") {
                    nearest shouldBeLessThanOrEqual case.spacing / 2 + case.epsilon()
                }
            }
        }
    }

    "tracks are straight and parallel at the requested angle (either way), one spacing apart or more" {
        checkAll(config, surveyCases) { case ->
            val plan = case.plan(CameraTrigger.PER_WAYPOINT)
            val along = Ne(cos(case.angleDegrees * PI / 180), sin(case.angleDegrees * PI / 180))
            for (points in plan.waypoints.filterNot { it.transit }.groupBy { it.track }.values) {
                val line = points.map { local(case.origin, it.location) }
                val length = line.first().distanceTo(line.last())
                if (length < 0.01) continue // too short for the angle to mean anything after the lat/lon round trip
                val sine = ((line.last().north - line.first().north) * along.east -
                    (line.last().east - line.first().east) * along.north) / length
                withClue("$case: track off the angle by asin($sine)") { abs(sine) shouldBeLessThanOrEqual 1e-6 }
                line.forEach { p -> distanceToSegment(p, line.first(), line.last()) shouldBeLessThanOrEqual case.epsilon() }
            }
        }
    }

    "no waypoint lies outside the polygon grown by the turnaround plus half a spacing; track ends within half a spacing" {
        // Why half a spacing more than the turnaround: full coverage forces it. Take a triangle
        // whose base is parallel to the tracks, half a spacing below the first track: the base's
        // corners are within s/2 of that track only if it reaches right above them, where the
        // triangle has already narrowed, i.e. up to s/2 outside it. A planner that kept the track
        // ends on the polygon would fail the coverage property instead.
        checkAll(config, surveyCases) { case ->
            val plan = case.plan()
            for (waypoint in plan.waypoints) {
                val outside = distanceOutside(case.local, local(case.origin, waypoint.location))
                val allowed = case.spacing / 2 + (if (waypoint.turnaround) case.turnaround else 0.0) + case.epsilon()
                withClue("$case: $waypoint is $outside m outside") { outside shouldBeLessThanOrEqual allowed }
            }
        }
    }

    "every point of the flown path, transits between tracks included, stays within turnaround + half a spacing" {
        checkAll(config, surveyCases) { case ->
            val path = case.plan().locations.map { local(case.origin, it) }
            val allowed = case.spacing / 2 + case.turnaround + case.epsilon()
            for ((a, b) in path.zipWithNext()) {
                for (k in 1..19) {
                    val p = Ne(a.north + (b.north - a.north) * k / 20, a.east + (b.east - a.east) * k / 20)
                    val outside = distanceOutside(case.local, p)
                    withClue("$case: leg $a → $b passes $outside m outside at $p") { outside shouldBeLessThanOrEqual allowed }
                }
            }
        }
    }

    "track length L obeys A/s ≤ L ≤ A/s + Σ|edge along track| (≤ A/s + perimeter)" {
        // Lower: each strip's track is at least as long as the polygon's chord anywhere in the
        // strip, so s × L ≥ the area. Upper: it is longer than a chord only by the along-track
        // extent of the polygon's edges inside the strip; the strips do not overlap.
        checkAll(config, surveyCases) { case ->
            val plan = case.plan()
            val area = shoelaceArea(case.local)
            val length = trackSegments(plan, case.origin).sumOf { (a, b) -> a.distanceTo(b) }
            val a = case.angleDegrees * PI / 180
            val edgesAlong = edges(case.local).sumOf { (p, q) -> abs((q.north - p.north) * cos(a) + (q.east - p.east) * sin(a)) }
            val slack = case.epsilon() * (plan.trackCount + 1)
            plan.trackLength.meters shouldBe (length plusOrMinus slack)
            length shouldBeGreaterThanOrEqual area / case.spacing - slack
            length shouldBeLessThanOrEqual area / case.spacing + edgesAlong + slack
        }
    }

    "total length of a convex survey ≤ A/s + 6 U + W + 2 n T (U, W: extent along and across the tracks)" {
        // Tracks: ≤ A/s + 2U (a convex outline crosses each along-track line twice). Turns between
        // neighbours: ≤ s + the shift of the track ends; the ends' sequence on either side is
        // unimodal for a convex polygon, so the shifts add up to ≤ 2U per side; the (n − 1) steps
        // of s add up to ≤ W; turnarounds add 2T per track.
        checkAll(config, surveyCases.filter { it.convex }) { case ->
            val plan = case.plan()
            val a = case.angleDegrees * PI / 180
            val u = case.local.map { it.north * cos(a) + it.east * sin(a) }
            val v = case.local.map { -it.north * sin(a) + it.east * cos(a) }
            val extentU = u.max() - u.min()
            val extentV = v.max() - v.min()
            val path = plan.locations.map { local(case.origin, it) }.zipWithNext { p, q -> p.distanceTo(q) }.sum()
            plan.totalLength.meters shouldBe (path plusOrMinus case.epsilon() * plan.locations.size)
            path shouldBeLessThanOrEqual shoelaceArea(case.local) / case.spacing + 6 * extentU + extentV +
                2 * plan.trackCount * case.turnaround + case.epsilon() * plan.locations.size
        }
    }

    "every transit from one track to the next, concave notches included, is at most 2T + s + P/2 long" {
        // A track's last waypoint X and the next one's first Y each lie within T + s/2 of their
        // nearest polygon points p, q; the planner flies X → (shortest path inside the polygon
        // from p to q) → Y, and that shortest path is at most half the perimeter P (the shorter
        // way round the boundary is one path inside). A router taking the long way would fail.
        checkAll(config, surveyCases) { case ->
            val plan = case.plan()
            val perimeter = edges(case.local).sumOf { (a, b) -> a.distanceTo(b) }
            val points = plan.waypoints.map { it to local(case.origin, it.location) }
            for (track in 1 until plan.trackCount) {
                val from = points.indexOfLast { it.first.track == track - 1 }
                val to = points.indexOfFirst { it.first.track == track && !it.first.transit }
                val length = (from until to).sumOf { points[it].second.distanceTo(points[it + 1].second) }
                length shouldBeLessThanOrEqual 2 * case.turnaround + case.spacing + perimeter / 2 + case.epsilon()
            }
        }
    }

    "entry: the first waypoint is the nearest to the start among the ends of the first and last tracks" {
        // For a convex polygon these are exactly the four corners of the one cell the planner
        // considers; for a concave one they are two of the cells' corners.
        checkAll(config, surveyCases) { case ->
            val plan = case.plan()
            val start = local(case.origin, case.start)
            val tracks = plan.waypoints.filterNot { it.transit }.groupBy { it.track }
            val candidates = listOf(tracks.getValue(0), tracks.getValue(plan.trackCount - 1))
                .flatMap { listOf(it.first(), it.last()) }
                .map { local(case.origin, it.location).distanceTo(start) }
            val first = local(case.origin, plan.locations.first()).distanceTo(start)
            first shouldBeLessThanOrEqual candidates.min() + case.epsilon()
        }
    }

    "photo per waypoint: photos along a track are at most the trigger distance apart, every track waypoint takes one" {
        checkAll(config, surveyCases, Arb.double(0.5, 300.0, includeNaNs = false)) { case, trigger ->
            val plan = PolygonSurvey.plan(
                case.polygon, 40.m, SurveySpacing.Direct(case.spacing.m, trigger.m),
                pod.core.units.Angle(case.angleDegrees), case.turnaround.m, case.start, CameraTrigger.PER_WAYPOINT,
            )
            for (points in plan.waypoints.groupBy { it.track }.values) {
                val photos = points.filter { !it.turnaround && !it.transit }
                photos.all { it.photo } shouldBe true
                points.filter { it.turnaround || it.transit }.none { it.photo } shouldBe true
                photos.map { local(case.origin, it.location) }.zipWithNext { p, q -> p.distanceTo(q) }
                    .forEach { it shouldBeLessThanOrEqual trigger + case.epsilon() }
            }
        }
    }

    "camera: footprint = sensor × altitude ÷ focal length, spacing and trigger distance follow the overlaps" {
        checkAll(
            config,
            Arb.double(1.0, 40.0, includeNaNs = false), Arb.double(2.0, 50.0, includeNaNs = false),
            Arb.double(5.0, 500.0, includeNaNs = false), Arb.double(0.0, 0.95, includeNaNs = false),
            Arb.int(100..10_000),
        ) { sensor, focal, altitude, overlap, pixels ->
            val camera = Camera(sensor.mm, (sensor * 2 / 3).mm, focal.mm, pixels, pixels * 2 / 3)
            val footprint = camera.footprint(altitude.m)
            footprint.across.meters shouldBe (sensor * altitude / focal plusOrMinus 1e-9 * altitude)
            footprint.along.meters shouldBe (sensor * 2 / 3 * altitude / focal plusOrMinus 1e-9 * altitude)
            camera.groundSamplingDistance(altitude.m).meters shouldBeGreaterThanOrEqual footprint.across.meters / pixels
            val square = listOf(0 to 0, 0 to 1000, 1000 to 1000, 1000 to 0).map { (n, e) -> surveyOrigin.offset(n.m, e.m) }
            val plan = PolygonSurvey.plan(square, 50.m, SurveySpacing.FromCamera(camera, altitude.m, overlap, overlap))
            plan.spacing.meters shouldBe (footprint.across.meters * (1 - overlap) plusOrMinus 1e-9 * altitude)
            plan.triggerDistance.meters shouldBe (footprint.along.meters * (1 - overlap) plusOrMinus 1e-9 * altitude)
        }
    }

    "bad input: each invalid case fails with a message naming it" {
        checkAll(config, surveyCases.filter { it.convex && it.polygon.size >= 4 }, Arb.int(0..100)) { case, pick ->
            val i = pick % case.polygon.size
            val j = (i + 1) % case.polygon.size
            val crossed = case.polygon.toMutableList().also { it[i] = case.polygon[j]; it[j] = case.polygon[i] }
            shouldThrow<IllegalArgumentException> { case.copy(polygon = crossed).plan() }.message!! shouldContain "self-intersecting"
            shouldThrow<IllegalArgumentException> { case.copy(polygon = case.polygon.take(pick % 3)).plan() }
                .message!! shouldContain "at least 3 points"
            shouldThrow<IllegalArgumentException> { case.copy(spacing = -case.spacing * pick / 100).plan() }
                .message!! shouldContain "track spacing"
            shouldThrow<IllegalArgumentException> {
                PolygonSurvey.plan(case.polygon, (-pick).m, SurveySpacing.Direct(case.spacing.m))
            }.message!! shouldContain "survey height"
            val camera = Camera(13.2.mm, 8.8.mm, 8.8.mm, 5472, 3648)
            shouldThrow<IllegalArgumentException> {
                SurveySpacing.FromCamera(camera, 100.m, frontOverlap = 1.0 + pick / 100.0, sideOverlap = 0.5)
            }.message!! shouldContain "front overlap"
        }
    }
})

private val surveyOrigin = pod.core.units.Location(47.4, 8.5)
