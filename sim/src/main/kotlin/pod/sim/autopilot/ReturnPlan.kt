package pod.sim.autopilot

import pod.core.units.Location
import pod.sim.flight.Body
import pod.sim.flight.Guidance
import pod.sim.flight.atAltitude
import pod.sim.flight.horizontalDistance

/**
 * A return to launch at [altitude] (AMSL; the caller picks the higher of the return altitude and
 * the current one for multirotors): climb there, fly home, then land there
 * (multirotors) or circle it at [loiterRadius] (planes). A multirotor climbs before it leaves;
 * a plane climbs on the way.
 */
internal class ReturnPlan(
    private val home: Location,
    private val altitude: Double,
    private val multirotor: Boolean,
    private val loiterRadius: Double,
    private val clockwise: Boolean,
) {
    private enum class Phase { CLIMB, RETURN, FINAL }

    private var phase = Phase.CLIMB

    /** True once a multirotor is descending over home. */
    val landing: Boolean get() = multirotor && phase == Phase.FINAL

    /** True once a plane reached home and circles it. */
    val circlingHome: Boolean get() = !multirotor && phase == Phase.FINAL

    /** What to fly now, from [body]. */
    fun guidance(body: Body): Guidance {
        if (phase == Phase.CLIMB) {
            if (multirotor && body.location.altitude.meters < altitude - 0.5) return Guidance.Climb(altitude)
            phase = Phase.RETURN
        }
        val target = atAltitude(home, altitude)
        if (phase == Phase.RETURN) {
            val arrived = horizontalDistance(body.location, home) < if (multirotor) 1.0 else loiterRadius * 1.5
            if (!arrived) return Guidance.GoTo(target)
            phase = Phase.FINAL
        }
        return if (multirotor) Guidance.Land(home) else Guidance.Loiter(target, loiterRadius, clockwise)
    }
}
