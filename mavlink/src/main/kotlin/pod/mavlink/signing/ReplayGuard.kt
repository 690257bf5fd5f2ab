package pod.mavlink.signing

/**
 * Replay protection for signed MAVLink 2 frames, as the signing specification asks of a receiver
 * (the signature check alone lets a recorded frame be played again):
 * - per stream — a (system id, component id, link id) triple — a frame's timestamp must be
 *   greater than the last one accepted from that stream;
 * - a stream not seen before is accepted only if its timestamp is no more than one minute
 *   ([NEW_STREAM_WINDOW], 6,000,000 units of 10 µs) behind the receiver's own signing time.
 *
 * Not thread-safe: feed it from the one thread that receives the link's frames.
 */
public class ReplayGuard {
    private val last = HashMap<Int, Long>()

    /**
     * Whether a frame from [systemId]/[componentId] on [linkId] with [timestamp] is fresh when the
     * receiver's own signing time is [now]; a fresh frame's timestamp becomes its stream's last.
     */
    public fun accept(systemId: Int, componentId: Int, linkId: Int, timestamp: Long, now: Long): Boolean {
        val stream = (systemId and 0xFF shl 16) or (componentId and 0xFF shl 8) or (linkId and 0xFF)
        val previous = last[stream]
        val fresh = if (previous == null) timestamp >= now - NEW_STREAM_WINDOW else timestamp > previous
        if (fresh) last[stream] = timestamp
        return fresh
    }

    /** The window a new signed stream's first timestamp must fall in. */
    public companion object {
        /** How far behind the receiver's time a new stream's first timestamp may be: one minute, in 10 µs units. */
        public const val NEW_STREAM_WINDOW: Long = 6_000_000
    }
}
