package pod.test

import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import pod.core.mission.SurveyDirection
import pod.core.queue.InsertMode
import pod.core.queue.QueueElement
import pod.core.queue.QueuePattern
import pod.core.queue.QueuePoint
import pod.core.queue.at
import pod.core.units.Distance
import pod.core.units.m
import kotlin.math.hypot
import kotlin.random.Random
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * Queue elements that keep a vehicle flying within [radius] of home: gotos, circles either way,
 * segments, paths, small surveys and holds (never a landing), each with or without a duration (up
 * to [longest]) and an altitude (in [heights]). Every point a pattern flies lies within [radius].
 */
public fun Arb.Companion.queueElement(
    radius: Distance = 200.m,
    longest: Duration = 60.seconds,
    heights: ClosedRange<Distance> = 10.m..60.m,
): Arb<QueueElement> {
    require(radius.meters >= 40) { "radius must be ≥ 40 m (room for a circle or a survey), was $radius" }
    require(longest >= 1.seconds && longest.isFinite()) { "longest must be ≥ 1 s and finite, was $longest" }
    require(heights.start.meters > 0 && heights.endInclusive >= heights.start) { "heights must be a range above 0 m, was $heights" }
    return arbitrary { rs ->
        val random = rs.random
        QueueElement(
            pattern = random.pattern(radius.meters),
            duration = if (random.nextBoolean()) null else random.nextLong(1, longest.inWholeSeconds + 1).seconds,
            altitude = if (random.nextBoolean()) null else random.within(heights.start.meters..heights.endInclusive.meters).m,
        )
    }
}

/**
 * What a program does to a queue: insertions in every [InsertMode] of [queueElement]s (drawn with
 * [radius]), `next()` and, rarely, a clear.
 */
public fun Arb.Companion.queueOperation(radius: Distance = 200.m): Arb<QueueOperation> {
    val elements = Arb.queueElement(radius)
    return arbitrary { rs ->
        when (rs.random.nextInt(10)) {
            in 0..6 -> QueueOperation.Insert(InsertMode.entries[rs.random.nextInt(InsertMode.entries.size)], elements.bind())
            in 7..8 -> QueueOperation.Next
            else -> QueueOperation.Clear
        }
    }
}

private fun Random.point(within: Double): QueuePoint = inDisc(within).let { (n, e) -> at(n.m, e.m) }

private fun Random.pattern(radius: Double): QueuePattern = when (nextInt(6)) {
    0 -> QueuePattern.Goto(point(radius))
    1 -> {
        val r = within(10.0..radius / 4)
        QueuePattern.Circle(point(radius - r), (if (nextBoolean()) r else -r).m)
    }
    2 -> QueuePattern.Segment(point(radius), point(radius))
    3 -> QueuePattern.Path(List(nextInt(2, 6)) { point(radius) })
    4 -> {
        val length = within(20.0..radius / 4)
        val width = within(20.0..radius / 4)
        // The rectangle reaches at most its diagonal from its start corner, whichever way it extends.
        val start = point(radius - hypot(length, width))
        QueuePattern.Survey(start, length.m, width.m, within(10.0..20.0).m, SurveyDirection.entries[nextInt(SurveyDirection.entries.size)])
    }
    else -> QueuePattern.Hold
}
