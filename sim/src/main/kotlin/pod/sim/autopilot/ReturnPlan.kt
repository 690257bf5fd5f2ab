package pod.sim.autopilot

import pod.core.units.Location
import pod.sim.flight.Body
import pod.sim.flight.Guidance
import pod.sim.flight.atAltitude
import pod.sim.flight.horizontalDistance

/**
 * A return to launch at [altitude] (AMSL; the caller picks the higher of the return altitude and
 * the current one for multirotors): climb there, fly home, then land there
 * (a multirotor) or circle it at [loiterRadius] (planes). A rotorcraft climbs before it leaves;
 * a plane climbs on the way.
 */
internal class ReturnPlan(
    private val home: Location,
    private val altitude: Double,
    /** The airframe hovers (physics: it climbs first and lands at home) rather than circling home. */
    private val rotorcraft: Boolean,
    private val loiterRadius: Double,
    private val clockwise: Boolean,
) {
    private enum class Phase { CLIMB, RETURN, FINAL }

    private var phase = Phase.CLIMB

    /** True once a rotorcraft is descending over home. */
    val landing: Boolean get() = rotorcraft && phase == Phase.FINAL

    /** True once a plane reached home and circles it. */
    val circlingHome: Boolean get() = !rotorcraft && phase == Phase.FINAL

    /** What to fly now, from [body]. */
    fun guidance(body: Body): Guidance {
        if (phase == Phase.CLIMB) {
            if (rotorcraft && body.location.altitude.meters < altitude - 0.5) return Guidance.Climb(altitude)
            phase = Phase.RETURN
        }
        val target = atAltitude(home, altitude)
        if (phase == Phase.RETURN) {
            val arrived = horizontalDistance(body.location, home) < if (rotorcraft) 1.0 else loiterRadius * 1.5
            if (!arrived) return Guidance.GoTo(target)
            phase = Phase.FINAL
        }
        return if (rotorcraft) Guidance.Land(home) else Guidance.Loiter(target, loiterRadius, clockwise)
    }
}
