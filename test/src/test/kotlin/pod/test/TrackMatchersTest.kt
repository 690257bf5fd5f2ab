package pod.test

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.should
import io.kotest.matchers.shouldNot
import io.kotest.matchers.string.shouldContain
import pod.core.units.m
import pod.test.MadeUpTracks.at
import pod.test.MadeUpTracks.circle
import pod.test.MadeUpTracks.home
import pod.test.MadeUpTracks.track
import kotlin.time.Duration.Companion.seconds

/** Each track matcher passes on a made-up track that keeps its rule, and fails on one that breaks it saying where and when. */
class TrackMatchersTest : StringSpec({

    // Out 100 m north at 30 m, with a 7 m sideways excursion at t = 3 s.
    val leg = track(listOf(0, 0, 0, 30), listOf(1, 25, 1, 30), listOf(2, 50, -2, 30), listOf(3, 70, 7, 30), listOf(4, 100, 0, 30))

    "stayInCorridor passes inside the corridor and fails where the track leaves it, naming the time and the offset" {
        leg should stayInCorridor(home, at(100, 0), width = 16.m)
        val failure = shouldThrow<AssertionError> { leg should stayInCorridor(home, at(100, 0), width = 10.m) }
        failure.message shouldContain "at 3s"
        failure.message shouldContain "7.0 m off"
        shouldThrow<AssertionError> { track() should stayInCorridor(home, at(100, 0), width = 10.m) }.message shouldContain "no points"
    }

    "circleAround tells clockwise from counter-clockwise by the signed area, and wants the turns it is asked for" {
        val center = at(50, 50)
        val ccw = circle(50.0 to 50.0, 20.0, turns = 1.5, clockwise = false)
        val cw = circle(50.0 to 50.0, 20.0, turns = 1.5, clockwise = true)
        ccw should circleAround(center, Turn.COUNTER_CLOCKWISE)
        cw should circleAround(center, Turn.CLOCKWISE, turns = 1.4)
        cw shouldNot circleAround(center, Turn.COUNTER_CLOCKWISE)
        shouldThrow<AssertionError> { ccw should circleAround(center, Turn.CLOCKWISE) }.message shouldContain "counter-clockwise"
        shouldThrow<AssertionError> { ccw should circleAround(center, Turn.COUNTER_CLOCKWISE, turns = 2.0) }.message shouldContain "540"
        // Around a point outside the circle the track sweeps no net area that way.
        shouldThrow<AssertionError> { ccw should circleAround(at(200, 200), Turn.COUNTER_CLOCKWISE) }
    }

    "landWithin passes for a flight that touches down near the point, and fails for one that lands far, stays up or never flew" {
        val flight = track(listOf(0, 0, 0, 0), listOf(10, 0, 0, 20), listOf(20, 40, 0, 20), listOf(30, 4, 2, 5), listOf(40, 4, 2, 0))
        flight should landWithin(5.m, of = home)
        val far = shouldThrow<AssertionError> { flight should landWithin(3.m, of = home) }
        far.message shouldContain "landed 4.5 m from"
        far.message shouldContain "40s"
        shouldThrow<AssertionError> { flight.between(0.seconds, 30.seconds) should landWithin(5.m, of = home) }.message shouldContain "still in the air"
        shouldThrow<AssertionError> { track(listOf(0, 0, 0, 0), listOf(5, 0, 0, 0)) should landWithin(5.m, of = home) }.message shouldContain "never left the ground"
    }

    "neverBelow ignores the ground near home and fails where the track is low farther out, saying when and how far out" {
        val flight = track(listOf(0, 0, 0, 0), listOf(5, 5, 0, 10), listOf(10, 40, 0, 30), listOf(20, 80, 0, 12), listOf(30, 5, 0, 0))
        flight should neverBelow(10.m, fartherThan = 10.m)
        val low = shouldThrow<AssertionError> { flight should neverBelow(20.m, fartherThan = 10.m) }
        low.message shouldContain "12.0 m above home at 20s"
        low.message shouldContain "80.0 m from home"
    }

    "holdAltitude passes within the tolerance over the window, fails outside it, and fails a window the track does not cover" {
        val hold = track(listOf(0, 0, 0, 29), listOf(10, 0, 0, 30.5), listOf(20, 0, 0, 31.8), listOf(30, 0, 0, 35))
        hold should holdAltitude(30.m, tolerance = 2.m, during = 0.seconds..20.seconds)
        shouldThrow<AssertionError> { hold should holdAltitude(30.m, tolerance = 2.m, during = 0.seconds..30.seconds) }.message shouldContain "at 30s: 35.0 m"
        shouldThrow<AssertionError> { hold should holdAltitude(30.m, tolerance = 2.m, during = 20.seconds..60.seconds) }.message shouldContain "does not cover"
    }

    "matchers refuse nonsense where they are made" {
        shouldThrow<IllegalArgumentException> { stayInCorridor(home, at(1, 1), width = 0.m) }
        shouldThrow<IllegalArgumentException> { circleAround(home, Turn.CLOCKWISE, turns = -1.0) }
    }
})
