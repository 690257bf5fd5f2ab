package pod.mavlink

import pod.core.units.toReadable
import kotlin.time.Duration

/**
 * An exchange with a vehicle that has gone unanswered for a while ([MavlinkVehicle.awaiting]):
 * what Pod waits for, how many times it has asked since the vehicle last answered, and for how
 * long, so that a person is not left in silence while Pod retries.
 */
public data class Awaiting(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** What is unanswered: "MAV_CMD_NAV_TAKEOFF", "parameter WPNAV_SPEED", "a mission transfer". */
    public val what: String,
    /** Requests sent since the vehicle last answered this exchange. */
    public val attempt: Int,
    /** How long the vehicle has not answered this exchange. */
    public val waited: Duration,
    /** The silence after which the exchange fails, when it has one. */
    public val giveUpAfter: Duration?,
) {
    /** One sentence for people: "no answer to MAV_CMD_NAV_TAKEOFF from vehicle 1 yet (attempt 3, 4.0 s of 10.0 s)". */
    public fun describe(): String =
        "no answer to $what from vehicle $systemId yet (attempt $attempt, ${waited.toReadable()}" +
            (giveUpAfter?.let { " of ${it.toReadable()}" } ?: "") + ")"
}
