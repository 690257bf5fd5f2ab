package pod.mavlink.mission

import pod.core.units.toReadable
import kotlin.time.Duration

/** A mission transfer (upload, download, clear, set-current) that did not succeed. */
public sealed class MissionException(message: String) : pod.core.PodException(message) {
    /** Which list the transfer concerned. */
    public abstract val type: MissionType
}

/**
 * The vehicle answered with an error [result]; [seq] is the item it concerned, when known, and
 * [explanation] what Pod makes of the refusal, when it knows more than the result says.
 */
public class MissionRejected(
    override val type: MissionType,
    /** What the vehicle said. */
    public val result: MissionResult,
    /** The item the vehicle most likely rejected (the last one it was sent), or null. */
    public val seq: Int?,
    operation: String,
    /** Why the vehicle most likely refused, and what Pod tried; null when the result says it all. */
    public val explanation: String? = null,
) : MissionException(
    "$operation of ${type.name.lowercase()} rejected by the vehicle: ${result.name}" + (seq?.let { " (at item $it)" } ?: "") +
        (explanation?.let { ": $it" } ?: ""),
)

/** No answer after [retries] timeouts in a row (the last one [lastTimeout] long). */
public class MissionTimeout(
    override val type: MissionType,
    /** Timeouts in a row that ended the transfer. */
    public val retries: Int,
    /** The last timeout waited. */
    public val lastTimeout: Duration,
    /** What the transfer was waiting for. */
    public val waitingFor: String,
    operation: String,
) : MissionException("$operation of ${type.name.lowercase()} timed out waiting for $waitingFor after $retries retries (last timeout ${lastTimeout.toReadable()})")

/** The items cannot be sent: [seq] names the first bad item and [reason] says why. */
public class InvalidMission(
    override val type: MissionType,
    /** The first bad item's position. */
    public val seq: Int,
    /** What is wrong with it. */
    public val reason: String,
) : MissionException("invalid ${type.name.lowercase()} item $seq: $reason")

/**
 * The upload's final MISSION_ACK never came and a download of what the vehicle holds differs from
 * what was sent: the vehicle may hold the old list, a partial one, or its own edit of ours.
 */
public class MissionNotConfirmed(
    override val type: MissionType,
    /** What the vehicle holds now. */
    public val onBoard: List<MissionItem>,
) : MissionException("upload of ${type.name.lowercase()} not confirmed: the vehicle never acknowledged it and holds ${onBoard.size} other items")

/**
 * [action] was refused before anything was sent: this service's last upload of the [type] list did
 * not complete (no final MISSION_ACK ACCEPTED, nor a download showing the list whole), and the
 * vehicle may hold it half-written. ArduPilot stores each mission item as it arrives, so it would fly
 * the new items up to where the upload stopped and the old ones after them.
 */
public class MissionHalfWritten(
    override val type: MissionType,
    /** What was refused ("start the mission", "resume the mission"). */
    public val action: String,
) : MissionException(
    "cannot $action: the last upload of the ${type.name.lowercase()} list did not complete, so the vehicle may hold it half-written " +
        "(ArduPilot stores each item as it arrives); upload it again first",
)
