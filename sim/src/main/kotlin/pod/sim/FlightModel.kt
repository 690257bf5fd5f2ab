package pod.sim

import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.LandedState
import kotlin.time.Duration
import kotlin.time.DurationUnit

/** A snapshot of a simulated vehicle's physical state. */
public data class SimState(
    /** Where it is (altitude above mean sea level). */
    public val location: Location,
    /** Home, where it booted. */
    public val home: Location,
    /** Velocity north, east, down in m/s. */
    public val velocityNed: Triple<Double, Double, Double> = Triple(0.0, 0.0, 0.0),
    /** Heading in degrees, 0..360. */
    public val headingDeg: Double = 0.0,
    /** Battery charge, 0..1. */
    public val charge: Double,
    /** Motors armed. */
    public val armed: Boolean = false,
    /** On the ground, in the air, … */
    public val landedState: LandedState = LandedState.ON_GROUND,
    /** The autopilot's custom_mode number. */
    public val customMode: Long = 0,
) {
    /** Height above home. */
    public val relativeAltitude: Distance get() = (location.altitude.meters - home.altitude.meters).m
}

/**
 * The physics of a simulated vehicle: advances its state by simulated time. For now it knows the
 * battery (drains while armed, recharges on the ground); flight under commands and missions plugs
 * in here.
 */
internal class FlightModel(initial: SimState) {
    var state: SimState = initial
        private set

    fun step(simulated: Duration) {
        val seconds = simulated.toDouble(DurationUnit.SECONDS)
        val s = state
        val charge = if (s.armed) s.charge - seconds / FULL_DRAIN_SECONDS else s.charge + seconds / FULL_RECHARGE_SECONDS
        state = s.copy(charge = charge.coerceIn(0.0, 1.0))
    }

    fun update(change: (SimState) -> SimState) {
        state = change(state)
    }

    private companion object {
        /** A full pack lasts 20 minutes of flight. */
        const val FULL_DRAIN_SECONDS = 20 * 60.0
        /** An empty pack is full again after an hour on the ground (a charging pad or a swap). */
        const val FULL_RECHARGE_SECONDS = 60 * 60.0
    }
}
