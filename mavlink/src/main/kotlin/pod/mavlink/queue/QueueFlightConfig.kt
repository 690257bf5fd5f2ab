package pod.mavlink.queue

import pod.core.PodException
import pod.core.queue.QueueEntry
import pod.core.units.Distance
import pod.core.units.m
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * How a [QueueFlight] flies; the defaults suit ArduPilot and PX4 vehicles. [refresh] and
 * [circleStep] are vehicle time (divided by the queue's time scale for a simulator running faster
 * than the clock); [statusPeriod] is wall time, for displays.
 */
public data class QueueFlightConfig(
    /**
     * How close to a point counts as reaching it, or null for the airframe's own: 2 m for a
     * multirotor; for a plane, which circles a point it reaches, its loiter radius (read once from
     * WP_LOITER_RAD or NAV_LOITER_RAD) and 20 m.
     */
    val arrivalRadius: Distance? = null,
    /** How close in altitude a multirotor must be to count as arrived. */
    val altitudeTolerance: Distance = 2.m,
    /** How often the current target is sent again, so a stale command taken late is put right. */
    val refresh: Duration = 3.seconds,
    /** How often an ArduCopter's ground-flown circle moves its target. */
    val circleStep: Duration = 500.milliseconds,
    /** The speed, m/s, to circle at where the autopilot takes one (PX4's orbit), and that the ground-flown circle's target leads. */
    val circleSpeed: Double = 5.0,
    /** How often the queue's status refreshes its remaining time. */
    val statusPeriod: Duration = 1.seconds,
    /** How long to wait for the vehicle's home. */
    val homeTimeout: Duration = 30.seconds,
    /** How long a land or return element may take to touch down. */
    val landingTimeout: Duration = 10.minutes,
    /** How long to wait for the loiter-radius parameter of a plane. */
    val paramTimeout: Duration = 10.seconds,
    /** The height an element with no altitude flies at when the vehicle reports none. */
    val defaultHeight: Distance = 30.m,
) {
    init {
        require(arrivalRadius == null || arrivalRadius.meters > 0) { "arrivalRadius must be > 0, was $arrivalRadius" }
        require(refresh.isPositive() && circleStep.isPositive() && statusPeriod.isPositive()) { "refresh, circleStep and statusPeriod must be > 0" }
        require(circleSpeed > 0) { "circleSpeed must be > 0, was $circleSpeed" }
    }

    internal companion object {
        val MULTIROTOR_ARRIVAL = 2.m
        val PLANE_LOITER_GUESS = 60.m
        val PLANE_ARRIVAL_MARGIN = 20.m
    }
}

/** A queue cannot be flown on this vehicle now. */
public class QueueNotFlyable(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** Why. */
    public val reason: String,
) : PodException("vehicle $systemId cannot fly the queue: $reason")

/** The vehicle refused what the queue's [entry] needed; the flight ends (the engine makes the vehicle safe). */
public class QueueElementRefused(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** The element being flown, if any. */
    public val entry: QueueEntry?,
    /** The vehicle's refusal, as the command or action that was refused reported it. */
    override val cause: PodException,
) : PodException("vehicle $systemId refused queue element ${entry ?: "(none)"}: ${cause.message}", cause)
