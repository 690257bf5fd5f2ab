package pod.mavlink.telemetry

import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Speed

/**
 * What a fixed-wing pilot's head-up display shows (VFR_HUD, common.xml): the speeds, climb rate,
 * heading and throttle the autopilot reports, as it reports them.
 */
public data class Hud(
    /** Airspeed (the autopilot's estimate when it has no airspeed sensor). */
    public val airspeed: Speed,
    /** Speed over the ground. */
    public val groundspeed: Speed,
    /** Altitude above mean sea level (as the autopilot reports it for this display). */
    public val altitude: Distance,
    /** Climb rate, positive up. */
    public val climbRate: Speed,
    /** Heading, 0..360 degrees, clockwise from north. */
    public val heading: Angle,
    /** Throttle in percent, 0..100. */
    public val throttle: Int,
)
