package pod.core.queue

import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asSharedFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.first
import pod.core.PodException
import pod.core.time.Timebase
import kotlin.time.Duration

/**
 * A vehicle's dynamic mission queue, in the spirit of Paparazzi's mission interface: elements are
 * added at any time ([append], [prepend], [replaceCurrent], [replaceAll]), the vehicle flies the
 * current one, and each ends when it reaches its end, when its duration runs out, or on [next].
 *
 * The queue itself flies nothing: a platform's queue flight (for MAVLink vehicles
 * `pod.mavlink.queue.QueueFlight`) follows [state], commands the vehicle, and reports arrivals
 * ([arrived]) and the passing of time ([expire]). Calls are safe from any thread; each change is
 * applied atomically and published on [state], [status] and [events]. Durations are counted on
 * [timebase]'s clock (pass the station's or the test scheduler's), in vehicle time: [timeScale]
 * seconds of it per second of that clock (a simulator running faster than the wall clock; in a
 * program, `missionQueue()` passes the platform's).
 */
public class MissionQueue(
    private val timebase: Timebase = Timebase.System,
    /** Seconds of vehicle time per second of the clock (1 for real vehicles). */
    public val timeScale: Double = 1.0,
) {
    init {
        require(timeScale > 0 && timeScale.isFinite()) { "timeScale must be a positive number, was $timeScale" }
    }

    private val origin = timebase.clock.markNow()
    private val _state = MutableStateFlow(QueueState())
    private val _status = MutableStateFlow(QueueStatus.EMPTY)
    private val _events = MutableSharedFlow<QueueEvent>(extraBufferCapacity = EVENT_BUFFER, onBufferOverflow = BufferOverflow.DROP_OLDEST)
    private val _flyer = MutableStateFlow<String?>(null)

    /** The queue's contents, changed atomically by every call. */
    public val state: StateFlow<QueueState> = _state.asStateFlow()

    /**
     * What a ground-station display shows, like Paparazzi's MISSION_STATUS: the current element, its
     * remaining time (null when unlimited) and the pending elements. The remaining time is refreshed
     * on every change and by the flight that flies the queue (about once a second).
     */
    public val status: StateFlow<QueueStatus> = _status.asStateFlow()

    /**
     * What happened, in order: elements started and ended (with why), and the queue running empty.
     * A collector that falls more than 256 events behind loses the oldest.
     */
    public val events: SharedFlow<QueueEvent> = _events.asSharedFlow()

    /** Who is flying the queue now (a vehicle's name), or null. */
    public val flyer: StateFlow<String?> = _flyer.asStateFlow()

    /** Vehicle time since the queue was made. */
    public fun now(): Duration = origin.elapsedNow() * timeScale

    /** Adds [element] at the end; it flies at once when the queue is empty. */
    public fun append(element: QueueElement): QueueEntry = insert(InsertMode.APPEND, element)

    /** Puts [element] before the current one, which resumes after it (with its whole duration). */
    public fun prepend(element: QueueElement): QueueEntry = insert(InsertMode.PREPEND, element)

    /** Drops the current element; [element] flies now. */
    public fun replaceCurrent(element: QueueElement): QueueEntry = insert(InsertMode.REPLACE_CURRENT, element)

    /** Empties the queue; [element] flies now. */
    public fun replaceAll(element: QueueElement): QueueEntry = insert(InsertMode.REPLACE_ALL, element)

    /** Inserts [element] by [mode] and returns the entry (with its id) it became. */
    public fun insert(mode: InsertMode, element: QueueElement): QueueEntry {
        var entry: QueueEntry? = null
        change { state, now -> state.insert(mode, element, now).also { entry = it.second }.first }
        return entry!!
    }

    /** Ends the current element now (Paparazzi's NEXT_MISSION) and returns it, or null when the queue was empty. */
    public fun next(): QueueEntry? {
        var ended: QueueEntry? = null
        change(EndReason.SKIPPED) { state, now -> ended = state.current; state.advance(now) }
        return ended
    }

    /** Empties the queue; the vehicle flying it holds where it is. */
    public fun clear() {
        change(EndReason.CLEARED) { state, _ -> state.cleared() }
    }

    /** Reports that element [id] reached its end; ignored when [id] is no longer current. */
    public fun arrived(id: Long) {
        change(EndReason.ARRIVED) { state, now -> state.arrived(id, now) }
    }

    /** Ends the current element if its duration has run out, and refreshes [status]'s remaining time. */
    public fun expire() {
        change(EndReason.ELAPSED) { state, now -> state.expire(now) }
    }

    /** Suspends until the queue holds something, and returns its current entry. */
    public suspend fun awaitElement(): QueueEntry = state.first { it.current != null }.current!!

    /** Suspends until the queue is empty. */
    public suspend fun awaitEmpty() {
        state.first { it.isEmpty }
    }

    /**
     * Marks the queue as flown by [who] until the returned function is called; throws [QueueBusy]
     * when another flight holds it (one queue steers one vehicle).
     */
    public fun claim(who: String): () -> Unit {
        if (!_flyer.compareAndSet(null, who)) throw QueueBusy(_flyer.value ?: "another flight", who)
        return { _flyer.compareAndSet(who, null) }
    }

    /**
     * Applies [transition] atomically at the current time, publishes the result and the events it
     * implies; a current element that changes without having been preempted or replaced ended for
     * [reason].
     */
    private fun change(reason: EndReason? = null, transition: (QueueState, Duration) -> QueueState): QueueState {
        val now = now()
        var before = _state.value
        var after: QueueState
        while (true) {
            before = _state.value
            after = transition(before, now)
            if (_state.compareAndSet(before, after)) break
        }
        // From the latest state, not this call's: whichever of two racing calls publishes last
        // publishes what both did.
        val latest = _state.value
        _status.value = QueueStatus(latest.current, latest.remaining(now), latest.pending)
        if (after !== before) announce(before, after, reason, now)
        return after
    }

    private fun announce(before: QueueState, after: QueueState, reason: EndReason?, now: Duration) {
        val old = before.current
        val new = after.current
        if (old?.id == new?.id) return
        if (old != null) {
            val why = when {
                after.pending.any { it.id == old.id } -> EndReason.PREEMPTED
                reason != null -> reason
                else -> EndReason.REPLACED
            }
            _events.tryEmit(QueueEvent.Ended(old, why, now))
        }
        if (new != null) _events.tryEmit(QueueEvent.Started(new, now)) else _events.tryEmit(QueueEvent.Emptied(now))
    }

    private companion object {
        const val EVENT_BUFFER = 256
    }
}

/** What a queue shows: see [MissionQueue.status]. */
public data class QueueStatus(
    /** The element being flown, or null. */
    val current: QueueEntry?,
    /** What is left of its duration, or null when it has none. */
    val remaining: Duration?,
    /** The elements after it, in order. */
    val pending: List<QueueEntry>,
) {
    /** The status every queue starts with. */
    public companion object {
        /** An empty queue. */
        public val EMPTY: QueueStatus = QueueStatus(null, null, emptyList())
    }
}

/** Something that happened in a [MissionQueue]; [at] is queue time. */
public sealed interface QueueEvent {
    /** When it happened, on the queue's clock. */
    public val at: Duration

    /**
     * [entry] became current.
     *
     * @property entry the element now flown, with its queue id.
     */
    public data class Started(val entry: QueueEntry, override val at: Duration) : QueueEvent

    /**
     * [entry] stopped being current, for [reason].
     *
     * @property entry the element that was flown, with its queue id.
     * @property reason why it stopped: it arrived, its time ran out, it was skipped, preempted, replaced or cleared.
     */
    public data class Ended(val entry: QueueEntry, val reason: EndReason, override val at: Duration) : QueueEvent

    /** The queue ran empty: the vehicle holds where it is. */
    public data class Emptied(override val at: Duration) : QueueEvent
}

/** Why an element stopped being current. */
public enum class EndReason {
    /** It reached its end. */
    ARRIVED,

    /** Its duration ran out. */
    ELAPSED,

    /** `next()` ended it. */
    SKIPPED,

    /** A prepended element went before it; it is pending again. */
    PREEMPTED,

    /** A replaceCurrent or replaceAll dropped it. */
    REPLACED,

    /** The queue was cleared. */
    CLEARED,
}

/** A second flight tried to fly a queue that [holder] is already flying. */
public class QueueBusy(
    /** Who flies it. */
    public val holder: String,
    /** Who asked. */
    public val asker: String,
) : PodException("the queue is already flown by $holder; $asker cannot fly it too (one queue steers one vehicle)")

/** What a flight of a queue does when the queue runs empty; either way the vehicle holds where it is. */
public enum class WhenEmpty {
    /** The flight completes (Paparazzi hands control back to the flight plan there). */
    COMPLETE,

    /** The flight goes on holding and flies whatever is added next, until cancelled. */
    WAIT,
}

/** The platform cannot fly a mission queue. */
public class QueueUnsupported(
    /** The platform's class name, as the message shows it. */
    public val platform: String,
) : PodException("$platform cannot fly a mission queue")

/** A queue task was bound to more than one vehicle: a queue steers one vehicle. */
public class QueueNeedsOneVehicle(
    /** How many it was bound to. */
    public val vehicles: Int,
) : PodException("a mission queue steers one vehicle, but the task was bound to $vehicles")
