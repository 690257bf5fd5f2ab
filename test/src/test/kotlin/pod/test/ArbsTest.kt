package pod.test

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.list
import io.kotest.property.checkAll
import pod.core.mission.LoiterDuration
import pod.core.mission.MissionStep
import pod.core.queue.MissionQueue
import pod.core.queue.QueuePattern
import pod.core.queue.QueuePoint
import pod.core.survey.PolygonSurvey
import pod.core.survey.SurveySpacing
import pod.core.units.m
import pod.sim.fault.LinkFaults
import pod.test.MadeUpTracks.home
import kotlin.math.abs
import kotlin.math.hypot
import kotlin.time.Duration.Companion.milliseconds

/** The Arbs draw what they promise: valid missions near home, simple polygons of both kinds, queue operations a queue takes, faults within bounds. */
class ArbsTest : StringSpec({

    "missions: built by the DSL, they take off first, end going home, and fly every point (loiter circles included) within the radius, unlimited loiters never" {
        checkAll(PropTestConfig(iterations = 300, seed = 1), Arb.mission(home, radius = 150.m)) { mission ->
            mission.home shouldBe home
            mission.steps.first().shouldBeInstanceOf<MissionStep.TakeOff>()
            (mission.steps.last() is MissionStep.Land || mission.steps.last() == MissionStep.ReturnHome) shouldBe true
            for (step in mission.steps.filterIsInstance<MissionStep.Navigation>()) {
                val circle = (step as? MissionStep.Loiter)?.radius?.meters ?: 0.0
                withClue(step) { home.distanceTo(step.location.copy(altitude = home.altitude)).meters + circle shouldBeLessThanOrEqual 150.0 + 1e-6 }
                (step as? MissionStep.Loiter)?.let { (it.duration is LoiterDuration.Unlimited) shouldBe false }
            }
        }
    }

    "polygons: simple (no two edges cross), convex and concave both drawn, every one plannable as a survey; convexPolygon only convex" {
        var concave = 0
        var convex = 0
        checkAll(PropTestConfig(iterations = 400, seed = 2), Arb.polygon(home, radius = 20.m..100.m, corners = 3..9)) { polygon ->
            val local = polygon.map { home.northEastTo(it).let { (n, e) -> n.meters to e.meters } }
            withClue(local) {
                Polygons.simple(local) shouldBe true
                local.forEach { (n, e) -> hypot(n, e) shouldBeLessThanOrEqual 100.0 + 1e-6 }
                PolygonSurvey.plan(polygon, 20.m, SurveySpacing.Direct(15.m)).waypoints.isNotEmpty() shouldBe true
            }
            if (Polygons.convex(local)) convex++ else concave++
        }
        withClue("convex $convex, concave $concave") { (convex > 20 && concave > 20) shouldBe true }
        checkAll(PropTestConfig(iterations = 200, seed = 3), Arb.convexPolygon(home)) { polygon ->
            Polygons.convex(polygon.map { home.northEastTo(it).let { (n, e) -> n.meters to e.meters } }) shouldBe true
        }
    }

    "queue operations: any sequence of them is taken by a queue, an insertion is held and a clear empties it, every point named lies within the radius" {
        checkAll(PropTestConfig(iterations = 200, seed = 4), Arb.list(Arb.queueOperation(radius = 120.m), 1..40)) { ops ->
            val queue = MissionQueue()
            for (op in ops) {
                op.applyTo(queue)
                if (op is QueueOperation.Insert) {
                    val held = listOfNotNull(queue.state.value.current) + queue.state.value.pending
                    withClue(op) { held.any { it.element == op.element } shouldBe true }
                    for (p in points(op.element.pattern)) withClue(op) { hypot(p.north.meters, p.east.meters) shouldBeLessThanOrEqual 120.0 + 1e-6 }
                }
                if (op == QueueOperation.Clear) queue.state.value.current shouldBe null
            }
        }
    }

    "link faults stay within their bound, and reach towards it" {
        val max = LinkFaults(drop = 0.25, duplicate = 0.1, reorder = 0.1, reorderDepth = 3, corrupt = 0.02, delay = 30.milliseconds, jitter = 5.milliseconds)
        var highestDrop = 0.0
        checkAll(PropTestConfig(iterations = 300, seed = 5), Arb.linkFaults(max)) { f ->
            f.drop shouldBeLessThanOrEqual max.drop
            f.duplicate shouldBeLessThanOrEqual max.duplicate
            f.reorder shouldBeLessThanOrEqual max.reorder
            f.corrupt shouldBeLessThanOrEqual max.corrupt
            (f.reorderDepth in 1..3 && f.delay <= max.delay && f.jitter <= max.jitter) shouldBe true
            highestDrop = maxOf(highestDrop, f.drop)
        }
        abs(highestDrop - max.drop) shouldBeLessThanOrEqual 0.02
    }
}) {
    private companion object {
        /** The points a pattern flies, with the corners of a survey rectangle. */
        fun points(pattern: QueuePattern): List<QueuePoint.Local> = when (pattern) {
            is QueuePattern.Goto -> listOf(pattern.point)
            is QueuePattern.Circle -> (pattern.center as QueuePoint.Local).let { c ->
                val r = abs(pattern.radius.meters)
                listOf(QueuePoint.Local(c.north + r.m, c.east), QueuePoint.Local(c.north - r.m, c.east), QueuePoint.Local(c.north, c.east + r.m), QueuePoint.Local(c.north, c.east - r.m))
            }
            is QueuePattern.Segment -> listOf(pattern.from, pattern.to)
            is QueuePattern.Path -> pattern.points
            is QueuePattern.Survey -> (pattern.start as QueuePoint.Local).let { s ->
                val n = pattern.length * pattern.direction.northSign.toDouble()
                val e = pattern.width * pattern.direction.eastSign.toDouble()
                listOf(s, QueuePoint.Local(s.north + n, s.east), QueuePoint.Local(s.north, s.east + e), QueuePoint.Local(s.north + n, s.east + e))
            }
            else -> emptyList()
        }.map { it as QueuePoint.Local }
    }
}
