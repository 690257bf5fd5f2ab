package pod.test

import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import pod.core.mission.Mission
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import pod.dsl.MissionBuilder
import pod.dsl.mission
import kotlin.random.Random
import kotlin.time.Duration.Companion.seconds

/**
 * Missions the `mission { }` builder accepts, flown from [home]: a take-off, then [legs] of
 * waypoints, relative moves, loiters (a few turns, or some seconds) and altitude changes, then
 * back home (landing there, or the autopilot's return to launch). Every point flown, loiter
 * circles included, lies within [radius] of home, at [heights] above it.
 */
public fun Arb.Companion.mission(
    home: Location,
    radius: Distance = 200.m,
    legs: IntRange = 1..5,
    heights: ClosedRange<Distance> = 10.m..60.m,
): Arb<Mission> {
    require(radius.meters >= 20) { "radius must be ≥ 20 m (room for a loiter circle), was $radius" }
    require(!legs.isEmpty() && legs.first >= 0) { "legs must be a non-empty range of counts ≥ 0, was $legs" }
    require(heights.start.meters >= 1 && heights.endInclusive >= heights.start) { "heights must be a range from ≥ 1 m, was $heights" }
    return arbitrary { rs ->
        val random = rs.random
        val count = random.nextInt(legs.first, legs.last + 1)
        mission("arbitrary mission") {
            home(home)
            takeOff(random.height(heights))
            repeat(count) { leg(random, home, radius.meters, heights) }
            if (random.nextBoolean()) returnHomeAndLand() else returnHome()
        }
    }
}

private fun Random.height(heights: ClosedRange<Distance>): Distance = within(heights.start.meters..heights.endInclusive.meters).m

/** One leg: a waypoint, a relative move, a loiter or an altitude change, all within [radius] of home. */
private fun MissionBuilder.leg(random: Random, home: Location, radius: Double, heights: ClosedRange<Distance>) {
    val height = random.height(heights)
    when (random.nextInt(5)) {
        0 -> random.inDisc(radius).let { (n, e) -> moveFromHome(n.m, e.m, height) }
        1 -> {
            // A relative move: drawn as a target inside the disc, given as the offset from here.
            val here = position!!
            val (n, e) = random.inDisc(radius)
            val (hn, he) = home.northEastTo(here).let { it.first.meters to it.second.meters }
            move((n - hn).m, (e - he).m, (height.meters - here.altitude.meters).m)
        }
        2, 3 -> {
            val circle = random.within(10.0..minOf(40.0, radius / 2))
            val (n, e) = random.inDisc(radius - circle)
            if (random.nextBoolean()) moveAndLoiterTurnsFromHome(n.m, e.m, height, turns = random.nextInt(1, 3), radius = circle.m)
            else moveAndLoiterTimeFromHome(n.m, e.m, height, time = random.nextInt(5, 31).seconds, radius = circle.m)
        }
        else -> altitude(height)
    }
}
