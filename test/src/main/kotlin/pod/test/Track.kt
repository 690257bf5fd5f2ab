package pod.test

import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import kotlin.math.hypot
import kotlin.time.Duration

/**
 * One sample of a flown track: when ([at], virtual time on the engine's clock, the axis of
 * [pod.core.engine.EngineEvent.at]), where ([location], altitude above mean sea level) and the
 * same place as metres [north], [east] and [up] from the track's home, and whether the vehicle was
 * [onGround] (its landed state), as the simulator's physics had it: what the vehicle really did,
 * not what its telemetry said.
 */
public data class TrackPoint(
    /** Virtual time since the program started. */
    public val at: Duration,
    /** Where the vehicle was. */
    public val location: Location,
    /** Metres north of home (negative: south). */
    public val north: Distance,
    /** Metres east of home (negative: west). */
    public val east: Distance,
    /** Height above home. */
    public val up: Distance,
    /** Whether the vehicle was on the ground. */
    public val onGround: Boolean,
) {
    /** Horizontal distance from home. */
    public val fromHome: Distance get() = hypot(north.meters, east.meters).m

    override fun toString(): String =
        "$at: ${north.meters.round1()} m N, ${east.meters.round1()} m E, ${up.meters.round1()} m up" +
            if (onGround) " (on the ground)" else ""

    /** Builds points from locations. */
    public companion object {
        /** The point [location] of a track whose home is [home], at [at]. */
        public fun of(at: Duration, location: Location, home: Location, onGround: Boolean): TrackPoint {
            val (north, east) = home.northEastTo(location)
            return TrackPoint(at, location, north, east, (location.altitude.meters - home.altitude.meters).m, onGround)
        }
    }
}

/**
 * The track one vehicle flew: [points] in time order, measured from [home] (where it booted,
 * altitude above mean sea level). Narrow it with [between] before asserting on a part of a flight.
 */
public class Track(
    /** The vehicle's system id. */
    public val vehicle: Int,
    /** The vehicle's name, as the platform gives it ("copter-1"). */
    public val name: String,
    /** Where heights and offsets are measured from. */
    public val home: Location,
    /** The samples, in time order. */
    public val points: List<TrackPoint>,
) {
    /** The part of this track from [from] to [to] (both included). */
    public fun between(from: Duration, to: Duration): Track = Track(vehicle, name, home, points.filter { it.at in from..to })

    /** The part of this track from [from] on. */
    public fun after(from: Duration): Track = Track(vehicle, name, home, points.filter { it.at >= from })

    /** [location] as metres north and east of [home]. */
    public fun local(location: Location): Pair<Distance, Distance> = home.northEastTo(location)

    override fun toString(): String =
        if (points.isEmpty()) "the empty track of $name" else "the track of $name (${points.size} points, ${points.first().at}..${points.last().at})"
}

internal fun Double.round1(): String = (kotlin.math.round(this * 10) / 10).toString()
