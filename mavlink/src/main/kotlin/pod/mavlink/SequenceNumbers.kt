package pod.mavlink

import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.atomic.AtomicInteger

/** Outgoing packet sequence numbers, one 0..255 counter per (system id, component id) we send as. */
internal class SequenceNumbers {
    private val counters = ConcurrentHashMap<Int, AtomicInteger>()

    /** The next sequence number for frames sent as ([systemId], [componentId]). */
    fun next(systemId: Int, componentId: Int): Int =
        counters.computeIfAbsent((systemId shl 8) or componentId) { AtomicInteger() }.getAndIncrement() and 0xFF
}

/** Counts frames received from one system and lost on the way (gaps in each component's sequence). */
internal class SequenceGaps {
    private val last = IntArray(256) { -1 }
    var received: Long = 0
        private set
    var lost: Long = 0
        private set

    fun record(componentId: Int, sequence: Int) {
        val previous = last[componentId]
        last[componentId] = sequence
        received++
        if (previous >= 0) {
            val gap = (sequence - previous - 1) and 0xFF
            // A gap of 255 is a repeated or reordered frame far more often than 255 lost ones.
            if (gap != 255) lost += gap
        }
    }
}
