package pod.mavlink.action

import kotlin.math.hypot
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Position

/**
 * Where a multirotor reported at a position can come to a stop: ahead along its velocity by its
 * braking distance v²/2a, plus what it flies while the report and the command cross the link.
 * The deceleration is a low guess (PX4's MPC_ACC_HOR defaults to 3 m/s², ArduCopter's
 * WPNAV_ACCEL to 2.5 m/s²), so the point lies at or just beyond where the vehicle would stop by
 * itself: it flies on a little rather than back.
 */
internal object StoppingPoint {
    /** The deceleration assumed, m/s². */
    const val DECELERATION = 2.5

    /** Seconds of flight allowed for the report's age and the command's way out. */
    const val LATENCY = 0.2

    /** The stopping point of a vehicle reported at [position]. */
    fun of(position: Position): Location {
        val vn = position.velocityNorth.metersPerSecond
        val ve = position.velocityEast.metersPerSecond
        val speed = hypot(vn, ve)
        if (speed < 0.2) return position.location
        val distance = speed * speed / (2 * DECELERATION) + speed * LATENCY
        return position.location.offset((vn / speed * distance).m, (ve / speed * distance).m)
    }
}
