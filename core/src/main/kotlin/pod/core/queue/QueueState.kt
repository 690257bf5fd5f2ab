package pod.core.queue

import kotlin.time.Duration

/**
 * The contents of a mission queue as a value: the [current] element, the [pending] ones in flying
 * order, and when [current] became current ([since], in the queue's own time). Every change is a
 * pure function of the state and the time, so property tests can drive it with no vehicle and no
 * clock; [MissionQueue] holds one of these and publishes it.
 */
public data class QueueState(
    /** The element being flown, or null when the queue is empty. */
    val current: QueueEntry? = null,
    /** The elements after [current], in order. */
    val pending: List<QueueEntry> = emptyList(),
    /** When [current] became current (queue time), or null when the queue is empty. */
    val since: Duration? = null,
    /** The id the next inserted element gets. */
    val nextId: Long = 1,
) {
    /** Whether nothing is queued. */
    val isEmpty: Boolean get() = current == null

    /** [current] then [pending]: everything the queue holds, in order. */
    val entries: List<QueueEntry> get() = listOfNotNull(current) + pending

    /**
     * This state with [element] inserted by [mode] at [now], and the entry it got. An insertion into
     * an empty queue makes the element current whatever the mode (Paparazzi's REPLACE_CURRENT on an
     * empty queue writes a slot it never flies; Pod flies it).
     */
    public fun insert(mode: InsertMode, element: QueueElement, now: Duration): Pair<QueueState, QueueEntry> {
        val entry = QueueEntry(nextId, element)
        val counted = copy(nextId = nextId + 1)
        val next = when {
            current == null -> counted.copy(current = entry, pending = emptyList(), since = now)
            else -> when (mode) {
                InsertMode.APPEND -> counted.copy(pending = pending + entry)
                InsertMode.PREPEND -> counted.copy(current = entry, pending = listOf(current) + pending, since = now)
                InsertMode.REPLACE_CURRENT -> counted.copy(current = entry, since = now)
                InsertMode.REPLACE_ALL -> counted.copy(current = entry, pending = emptyList(), since = now)
            }
        }
        return next to entry
    }

    /** This state with the current element ended at [now]: the first pending one becomes current. */
    public fun advance(now: Duration): QueueState {
        val head = pending.firstOrNull()
        return copy(current = head, pending = pending.drop(1), since = if (head == null) null else now)
    }

    /** This state after element [id] reached its end at [now]; unchanged when [id] is not current (a late report). */
    public fun arrived(id: Long, now: Duration): QueueState = if (current?.id == id) advance(now) else this

    /** When the current element's duration runs out (queue time), or null when it has none. */
    public val deadline: Duration?
        get() = current?.element?.limit?.let { limit -> since?.plus(limit) }

    /** This state at [now]: the current element ended if its duration has run out. */
    public fun expire(now: Duration): QueueState = deadline?.let { if (now >= it) advance(it) else this } ?: this

    /** How much of the current element's duration is left at [now], or null when it has none. */
    public fun remaining(now: Duration): Duration? = deadline?.let { (it - now).coerceAtLeast(Duration.ZERO) }

    /** This state emptied (ids keep counting). */
    public fun cleared(): QueueState = QueueState(nextId = nextId)
}
