package pod.mavlink.codec

/**
 * Stream parser from bytes to [MavFrame]s, for one source (one UDP peer or one TCP connection).
 *
 * Accepts MAVLink 1 and 2 interleaved, several frames per datagram and frames split across
 * datagrams (a partial frame at the end of one feed is completed by the next). CRC_EXTRA is checked
 * for every message the dialect knows; frames of unknown message ids pass through undecoded.
 * Garbage, truncated and bad-CRC bytes are skipped and counted in [stats]: [feed] never throws on
 * any input. Not thread-safe: one decoder per source, fed from one coroutine.
 */
public class FrameDecoder(private val codec: MessageCodec = MessageCodec.Default) {

    /** What this decoder has seen so far. */
    public val stats: DecoderStats = DecoderStats()

    /** Parses [length] bytes of [bytes] from [offset], calling [sink] for each complete valid frame. */
    public fun feed(bytes: ByteArray, offset: Int = 0, length: Int = bytes.size - offset, sink: (MavFrame) -> Unit): Unit = TODO()
}

/** Counters of a [FrameDecoder]; plain fields, read them from the decoder's own coroutine or accept slight staleness. */
public class DecoderStats {
    /** Valid frames delivered. */
    public var frames: Long = 0
        internal set
    /** Frames dropped because their CRC did not match. */
    public var badCrc: Long = 0
        internal set
    /** Bytes skipped while looking for a frame start (garbage, or the start of a rejected frame). */
    public var skippedBytes: Long = 0
        internal set
    /** Delivered frames whose message id the dialect does not know (CRC could not be checked). */
    public var unknownMessages: Long = 0
        internal set
}
