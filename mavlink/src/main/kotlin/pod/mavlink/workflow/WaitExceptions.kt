package pod.mavlink.workflow

import pod.core.PodException
import pod.core.units.toReadable
import kotlin.time.Duration

/** Vehicle [systemId] did not report [awaited] within [waited]: the message names what Pod waited for. */
public class NothingReported(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** What Pod waited for, in MAVLink's words (the messages that would have answered). */
    public val awaited: String,
    /** How long Pod waited. */
    public val waited: Duration,
) : PodException("vehicle $systemId reported no $awaited within ${waited.toReadable()}")

/** A waypoint action did not finish within its [Stop.timeout] ([limit]). */
public class WaypointActionTimeout(
    /** The waypoint's number. */
    public val index: Int,
    /** The action's time limit (vehicle time). */
    public val limit: Duration,
) : PodException("the action at waypoint $index did not finish within its time limit of ${limit.toReadable()}")
