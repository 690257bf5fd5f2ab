package pod.cli.gcs

import pod.cli.json.Event

/**
 * What one page has still to be sent, gathered between two batches: events in the order they
 * happened ([add]: the log, replies, a vehicle found) and states of which only the latest counts
 * ([latest]: a vehicle's telemetry, a queue's status). [drain] empties both into the next batch.
 *
 * A page that falls behind loses its oldest events beyond [maxEvents], never the latest states,
 * and is told how many it lost, so a slow browser cannot make the server's memory grow.
 */
public class PageFeed(
    private val maxEvents: Int = 5_000,
    /** Told of each event dropped (the server's count, [GcsStats.eventsDropped]). */
    private val onDrop: () -> Unit = {},
) {
    private val events = ArrayDeque<Event>()
    private val states = LinkedHashMap<String, Event>()
    private var dropped = 0L

    /** Queues [event] for the next batch. */
    public fun add(event: Event): Unit = synchronized(this) {
        events.addLast(event)
        if (events.size > maxEvents) {
            events.removeFirst()
            dropped++
            onDrop()
        }
    }

    /** Makes [event] the state sent under [key] in the next batch, replacing one not yet sent. */
    public fun latest(key: String, event: Event): Unit = synchronized(this) {
        states[key] = event
    }

    /** Everything queued since the last call, events first then states; empty when nothing was. */
    public fun drain(): List<Event> = synchronized(this) {
        val out = ArrayList<Event>(events.size + states.size + 1)
        if (dropped > 0) out += Event.Warning("this page fell behind: $dropped events were not sent")
        out += events
        out += states.values
        events.clear()
        states.clear()
        dropped = 0
        out
    }
}
