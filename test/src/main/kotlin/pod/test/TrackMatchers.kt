package pod.test

import io.kotest.matchers.Matcher
import io.kotest.matchers.MatcherResult
import pod.core.units.Distance
import pod.core.units.Location
import kotlin.time.Duration

// kotest matchers on flown tracks: `record.track(1) should landWithin(3.m, of = home)`.
// Each failure says where and when the track broke the rule, in metres from the track's home.

/** Which way a vehicle turns, seen from above. */
public enum class Turn {
    /** Clockwise seen from above (a positive queue circle radius). */
    CLOCKWISE,

    /** Counter-clockwise seen from above. */
    COUNTER_CLOCKWISE,
}

/**
 * Passes when every point of the track lies within half of [width] of the segment from [from] to
 * [to] (horizontally; heights are not checked). Narrow the track to the leg first
 * (`track.between(…)`); an empty track fails, since it shows nothing.
 */
public fun stayInCorridor(from: Location, to: Location, width: Distance): Matcher<Track> {
    require(width.meters > 0) { "width must be > 0, was $width" }
    return Matcher { track -> inCorridor(track, from, to, width) }
}

private fun inCorridor(track: Track, from: Location, to: Location, width: Distance): MatcherResult {
    val a = track.local(from).let { it.first.meters to it.second.meters }
    val b = track.local(to).let { it.first.meters to it.second.meters }
    val half = width.meters / 2
    val worst = track.points.maxByOrNull { offSegment(it.north.meters, it.east.meters, a, b) }
    val firstOut = track.points.firstOrNull { offSegment(it.north.meters, it.east.meters, a, b) > half }
    val corridor = "the ${width.meters.round1()} m corridor from (${a.first.round1()} N, ${a.second.round1()} E) to (${b.first.round1()} N, ${b.second.round1()} E)"
    return MatcherResult(
        track.points.isNotEmpty() && firstOut == null,
        {
            if (firstOut == null) "$track has no points to keep in $corridor"
            else "${track.name} left $corridor at ${firstOut.at}: ${offSegment(firstOut.north.meters, firstOut.east.meters, a, b).round1()} m off its centre line " +
                "(at most ${half.round1()} allowed), at $firstOut; farthest: $worst"
        },
        { "${track.name} stayed in $corridor, farthest ${worst?.let { offSegment(it.north.meters, it.east.meters, a, b).round1() }} m off its centre line" },
    )
}

/**
 * Passes when the track goes around [center] in [direction] (the sign of the area it sweeps
 * around the centre) by at least [turns] full turns in that direction.
 */
public fun circleAround(center: Location, direction: Turn, turns: Double = 1.0): Matcher<Track> {
    require(turns >= 0 && turns.isFinite()) { "turns must be ≥ 0 and finite, was $turns" }
    return Matcher { track -> circling(track, center, direction, turns) }
}

private fun circling(track: Track, center: Location, direction: Turn, turns: Double): MatcherResult {
    val c = track.local(center).let { it.first.meters to it.second.meters }
    val points = track.points.map { it.northEast }
    val area = signedArea(points, c) / 2
    val degrees = degreesAround(points, c)
    val wanted = if (direction == Turn.COUNTER_CLOCKWISE) 1.0 else -1.0
    val turned = if (area > 0) Turn.COUNTER_CLOCKWISE else Turn.CLOCKWISE
    val span = if (track.points.isEmpty()) "no points" else "${track.points.first().at}..${track.points.last().at}"
    val what = "${track.name} around (${c.first.round1()} N, ${c.second.round1()} E) in $span swept a signed area of ${area.round1()} m² " +
        "(${turned.name.lowercase().replace('_', '-')}) and ${degrees.round1()}° (counter-clockwise positive)"
    return MatcherResult(
        area * wanted > 0 && degrees * wanted >= turns * 360,
        { "$what; expected at least $turns ${direction.name.lowercase().replace('_', '-')} turn(s), ${(turns * 360 * wanted).round1()}°" },
        { "$what; expected it not to circle ${direction.name.lowercase().replace('_', '-')} $turns turn(s)" },
    )
}

/**
 * Passes when the track ends on the ground within [distance] (horizontally) of [of], having been
 * in the air before: a flight that landed there, not a vehicle that never left.
 */
public fun landWithin(distance: Distance, of: Location): Matcher<Track> = Matcher { track ->
    val target = track.local(of).let { it.first.meters to it.second.meters }
    val last = track.points.lastOrNull()
    val flew = track.points.any { !it.onGround }
    val touchdown = track.points.indexOfLast { !it.onGround }.let { track.points.getOrNull(it + 1) }
    val off = last?.let { kotlin.math.hypot(it.north.meters - target.first, it.east.meters - target.second) }
    val where = "(${target.first.round1()} N, ${target.second.round1()} E)"
    MatcherResult(
        last != null && flew && last.onGround && off!! <= distance.meters,
        {
            when {
                last == null -> "$track has no points, so it shows no landing near $where"
                !flew -> "${track.name} never left the ground, so it did not land near $where"
                !last.onGround -> "${track.name} was still in the air at its last point, $last, ${off!!.round1()} m from $where"
                else -> "${track.name} landed ${off!!.round1()} m from $where (at most ${distance.meters.round1()} allowed): touched down at ${touchdown ?: last}, ended at $last"
            }
        },
        { "${track.name} landed ${off?.round1()} m from $where, within ${distance.meters.round1()} m" },
    )
}

/**
 * Passes when the track is never lower than [height] above home wherever it is farther than
 * [fartherThan] (horizontally) from home: take-off and landing happen near home, nowhere else.
 */
public fun neverBelow(height: Distance, fartherThan: Distance): Matcher<Track> = Matcher { track ->
    val away = track.points.filter { it.fromHome > fartherThan }
    val low = away.firstOrNull { it.up < height }
    MatcherResult(
        low == null,
        {
            "${track.name} was ${low!!.up.meters.round1()} m above home at ${low.at}, ${low.fromHome.meters.round1()} m from home, " +
                "below the ${height.meters.round1()} m it must keep farther than ${fartherThan.meters.round1()} m out: $low"
        },
        { "${track.name} never went below ${height.meters.round1()} m farther than ${fartherThan.meters.round1()} m from home (${away.size} points out there)" },
    )
}

/**
 * Passes when the track stays within [tolerance] of [height] above home throughout [during]; the
 * track must cover the whole window (a window with no samples shows nothing and fails).
 */
public fun holdAltitude(height: Distance, tolerance: Distance, during: ClosedRange<Duration>): Matcher<Track> = Matcher { track ->
    val inside = track.points.filter { it.at in during }
    val covered = track.points.isNotEmpty() && track.points.first().at <= during.start && track.points.last().at >= during.endInclusive
    val off = inside.firstOrNull { kotlin.math.abs(it.up.meters - height.meters) > tolerance.meters }
    val rule = "${height.meters.round1()} ± ${tolerance.meters.round1()} m above home from ${during.start} to ${during.endInclusive}"
    MatcherResult(
        covered && inside.isNotEmpty() && off == null,
        {
            if (!covered || inside.isEmpty()) "$track does not cover the window of $rule"
            else "${track.name} left $rule at ${off!!.at}: ${off.up.meters.round1()} m above home, at $off"
        },
        { "${track.name} held $rule" },
    )
}
