package pod.core.queue

import pod.core.units.Distance
import kotlin.time.Duration

/**
 * One element of a [MissionQueue]: a [pattern], an optional [duration] and an optional [altitude].
 *
 * As in Paparazzi's mission interface, a goto, segment, path or survey ends when its end is reached
 * or its duration runs out, whichever comes first; a circle or a hold ends only when its duration
 * runs out (or on `next()`); a duration of zero or less means none and is stored as null. A
 * duration is counted from the moment the element becomes current, afresh each time it does (after
 * a prepend it resumes with its whole duration).
 */
public data class QueueElement(
    /** What to fly. */
    val pattern: QueuePattern,
    /** How long at most, or null for no limit. */
    val duration: Duration? = null,
    /** Height above home to fly at, or null to keep the height the vehicle has when the element starts. */
    val altitude: Distance? = null,
) {
    init {
        require(altitude == null || (altitude.meters > 0 && altitude.meters <= MAX_ALTITUDE_M)) { "altitude must be in (0, ${MAX_ALTITUDE_M.toInt()}] m above home, was $altitude" }
        require(duration == null || !duration.isInfinite()) { "duration must be finite (leave it out for no limit), was $duration" }
    }

    /** [duration] when it is positive, else null (Paparazzi: ≤ 0 means none). */
    val limit: Duration? get() = duration?.takeIf { it.isPositive() }

    override fun toString(): String = buildString {
        append(pattern)
        altitude?.let { append(" at ").append(it) }
        limit?.let { append(" for ").append(it) }
    }

    /** The limits every element is checked against when it is made. */
    public companion object {
        /** The highest altitude above home an element may ask for. */
        public const val MAX_ALTITUDE_M: Double = 10_000.0
    }
}

/**
 * An element in a queue, with the [id] the queue gave it.
 *
 * @property id the queue's number for the element: ids grow and are never reused, so an id names one insertion.
 * @property element what is flown.
 */
public data class QueueEntry(val id: Long, val element: QueueElement) {
    override fun toString(): String = "#$id $element"
}

/** Where [MissionQueue.insert] puts a new element (Paparazzi's insertion modes). */
public enum class InsertMode {
    /** At the end of the queue. */
    APPEND,

    /** Before the current element, which stays in the queue and resumes after the new one. */
    PREPEND,

    /** In place of the current element, which is dropped; the new one flies now. */
    REPLACE_CURRENT,

    /** The queue is emptied; the new element flies now. */
    REPLACE_ALL,
}
