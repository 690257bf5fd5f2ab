package pod.test

import pod.core.queue.InsertMode
import pod.core.queue.MissionQueue
import pod.core.queue.QueueElement

/**
 * What a program does to a [MissionQueue] while a vehicle flies it, as a value a property test
 * can draw ([queueOperation]) and replay on a queue with [applyTo].
 */
public sealed interface QueueOperation {
    /** Does this to [queue]. */
    public fun applyTo(queue: MissionQueue)

    /** Inserts [element] where [mode] says. */
    public data class Insert(
        /** Where the element goes. */
        public val mode: InsertMode,
        /** What is inserted. */
        public val element: QueueElement,
    ) : QueueOperation {
        override fun applyTo(queue: MissionQueue) {
            queue.insert(mode, element)
        }
    }

    /** Ends the current element; the next one flies. */
    public data object Next : QueueOperation {
        override fun applyTo(queue: MissionQueue) {
            queue.next()
        }
    }

    /** Empties the queue. */
    public data object Clear : QueueOperation {
        override fun applyTo(queue: MissionQueue) {
            queue.clear()
        }
    }
}
