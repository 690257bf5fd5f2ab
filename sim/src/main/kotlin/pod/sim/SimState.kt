package pod.sim

import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.Speed
import pod.core.units.deg
import pod.core.units.m
import pod.core.vehicle.LandedState
import kotlin.math.hypot
import kotlin.time.Duration

/** A snapshot of a simulated vehicle: its physical state and what its autopilot is doing. */
public data class SimState(
    /** Where it is (altitude above mean sea level). */
    public val location: Location,
    /** Home: where it booted, or where DO_SET_HOME moved it. */
    public val home: Location,
    /** Velocity north, east, down. */
    public val velocityNed: Triple<Speed, Speed, Speed> = Triple(Speed.ZERO, Speed.ZERO, Speed.ZERO),
    /** Heading, 0..360°. */
    public val heading: Angle = 0.deg,
    /** Battery charge, 0..1. */
    public val charge: Double,
    /** Motors armed. */
    public val armed: Boolean = false,
    /** On the ground, in the air, … */
    public val landedState: LandedState = LandedState.ON_GROUND,
    /** The autopilot's custom_mode number. */
    public val customMode: Long = 0,
    /** The flight mode's name ("GUIDED", "AUTO.MISSION", …). */
    public val modeName: String = "",
    /** Airspeed (no wind: the speed through the air along the heading). */
    public val airspeed: Speed = Speed.ZERO,
    /** Throttle in percent, 0..100. */
    public val throttle: Int = 0,
    /** The mission item being executed (MISSION_CURRENT's seq). */
    public val missionCurrent: Int = 0,
    /** True once the simulated GPS has a 3D fix and the estimator is ready (arming is possible). */
    public val positionReady: Boolean = true,
    /**
     * Where the autopilot is steering now: a guided go-to's point (DO_REPOSITION, a guided
     * waypoint) or, in a mission, the position of the item being flown; null while it holds, takes
     * off, lands or does anything else. Lets tests and benchmarks see a command take effect at the
     * vehicle, not only in its telemetry.
     */
    public val target: Location? = null,
    /** Elevation above mean sea level of the ground straight below it (home's altitude over flat ground). */
    public val groundAltitude: Distance = home.altitude,
    /** The vehicle's own clock when this snapshot was taken: simulated time since it was made. */
    public val time: Duration = Duration.ZERO,
    /** Why the simulator ended the flight ("flew into terrain"), or null while it has not. */
    public val crashed: String? = null,
) {
    /** Height above the ground straight below it: what a downward rangefinder measures. */
    public val heightAboveGround: Distance get() = (location.altitude.meters - groundAltitude.meters).m

    /** Height above home. */
    public val relativeAltitude: Distance get() = (location.altitude.meters - home.altitude.meters).m

    /** Altitude above mean sea level. */
    public val altitudeAmsl: Distance get() = location.altitude

    /** Horizontal speed over the ground. */
    public val groundSpeed: Speed get() = Speed(hypot(velocityNed.first.metersPerSecond, velocityNed.second.metersPerSecond))

    /** Climb rate, positive up. */
    public val climbRate: Speed get() = Speed(-velocityNed.third.metersPerSecond)
}
