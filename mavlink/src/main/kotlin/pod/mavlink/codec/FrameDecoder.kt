package pod.mavlink.codec

/**
 * Stream parser from bytes to [MavFrame]s, for one source (one UDP peer or one TCP connection).
 *
 * Accepts MAVLink 1 and 2 interleaved, several frames per datagram and frames split across
 * datagrams (a partial frame at the end of one feed is completed by the next). CRC_EXTRA is checked
 * for every message the dialect knows; frames of unknown message ids pass through undecoded.
 * Garbage, truncated and bad-CRC bytes are skipped and counted in [stats]: [feed] never throws on
 * any input. Not thread-safe: one decoder per source, fed from one coroutine.
 *
 * After a CRC mismatch the parser moves one byte past the rejected frame's magic and searches
 * again, so a valid frame hidden inside the rejected one is still found. MAVLink 2 frames with
 * incompatibility flags other than "signed" are rejected the same way. Signatures are kept, not
 * verified. Frames of unknown ids cannot be checked: their length is taken on trust, so garbage
 * that looks like such a header can hide up to 280 following bytes (any run of 280 bytes without
 * a magic byte resynchronises the parser).
 */
public class FrameDecoder(private val codec: MessageCodec = MessageCodec.Default) {

    /** What this decoder has seen so far. */
    public val stats: DecoderStats = DecoderStats()

    /** Bytes received but not yet parsed: [head] until [tail]. Never grows; see [feed]. */
    private val buffer = ByteArray(BUFFER_SIZE)
    private var head = 0
    private var tail = 0

    /** The one view every frame is read through (see [feedViews]). */
    private val view = FrameView()

    /** The sink of the [feed] in progress, and what hands it a copied frame: made once, not per call. */
    private var frameSink: ((MavFrame) -> Unit)? = null
    private val copier = FrameViewSink { view -> frameSink!!(view.toFrame()) }

    /** Bytes kept for the next [feed]: the start of an incomplete frame, always under [FrameLayout.MAX_FRAME]. */
    internal val pendingBytes: Int get() = tail - head

    /**
     * Parses [length] bytes of [bytes] from [offset], calling [sink] for each complete valid frame.
     *
     * Frames are delivered in stream order, each with its own payload copy. An incomplete frame at
     * the end is kept (at most 279 bytes) and completed by the next call. If [sink] throws, the
     * exception propagates and the rest of this call's bytes (and any partial frame kept from
     * earlier calls) are dropped; the decoder stays usable.
     * Throws IndexOutOfBoundsException only when [offset] and [length] do not lie within [bytes].
     */
    public fun feed(bytes: ByteArray, offset: Int = 0, length: Int = bytes.size - offset, sink: (MavFrame) -> Unit) {
        frameSink = sink
        try {
            feedViews(bytes, offset, length, copier)
        } finally {
            frameSink = null
        }
    }

    /**
     * [feed] without copying: [sink] is called for each complete valid frame with this decoder's
     * one [FrameView], pointing into its buffer and valid only during that call. The ground
     * station's receive path: a frame it can read in place allocates nothing.
     */
    internal fun feedViews(bytes: ByteArray, offset: Int, length: Int, sink: FrameViewSink) {
        if (offset < 0 || length < 0 || offset > bytes.size - length) {
            throw IndexOutOfBoundsException("offset $offset and length $length outside ${bytes.size} bytes")
        }
        var position = offset
        val end = offset + length
        try {
            while (position < end) {
                compact()
                // Copying through the buffer costs one arraycopy per byte, far less than the CRC, and
                // keeps a single code path for frames that span feeds.
                val count = minOf(buffer.size - tail, end - position)
                bytes.copyInto(buffer, tail, position, position + count)
                tail += count
                position += count
                parse(sink)
            }
        } catch (failure: Throwable) {
            // Only the sink can throw here. Drop what is buffered so the next feed starts clean
            // instead of replaying half of this one.
            head = 0
            tail = 0
            throw failure
        }
    }

    /** Moves the unparsed bytes (at most one partial frame) to the start of [buffer]. */
    private fun compact() {
        if (head == 0) return
        buffer.copyInto(buffer, 0, head, tail)
        tail -= head
        head = 0
    }

    /** Delivers every complete frame in the buffer; leaves [head] at a partial frame's magic, or at [tail]. */
    private fun parse(sink: FrameViewSink) {
        val buf = buffer
        while (head < tail) {
            val start = head
            val magic = buf[start].toInt() and 0xFF
            if (magic != FrameLayout.MAGIC_V1 && magic != FrameLayout.MAGIC_V2) {
                skip()
                continue
            }
            val available = tail - start
            if (available < 3) return // length and (MAVLink 2) incompat flags not here yet
            val payloadLength = buf[start + 1].toInt() and 0xFF
            val version: Int
            val headerLength: Int
            val signatureLength: Int
            if (magic == FrameLayout.MAGIC_V2) {
                val incompat = buf[start + 2].toInt() and 0xFF
                if (incompat and FrameLayout.FLAG_SIGNED.inv() != 0) {
                    skip() // a flag this parser does not know: the frame cannot be read safely
                    continue
                }
                version = 2
                headerLength = FrameLayout.HEADER_V2
                signatureLength = if (incompat and FrameLayout.FLAG_SIGNED != 0) FrameLayout.SIGNATURE else 0
            } else {
                version = 1
                headerLength = FrameLayout.HEADER_V1
                signatureLength = 0
            }
            val checksumAt = start + headerLength + payloadLength
            val frameLength = headerLength + payloadLength + FrameLayout.CHECKSUM + signatureLength
            if (available < frameLength) return // wait for the rest
            val messageId = if (version == 2) {
                (buf[start + 7].toInt() and 0xFF) or ((buf[start + 8].toInt() and 0xFF) shl 8) or
                    ((buf[start + 9].toInt() and 0xFF) shl 16)
            } else {
                buf[start + 5].toInt() and 0xFF
            }
            val crcExtra = codec.crcExtra(messageId)
            if (crcExtra >= 0) {
                val expected = Crc.frameChecksum(buf, start + 1, headerLength - 1 + payloadLength, crcExtra)
                val actual = (buf[checksumAt].toInt() and 0xFF) or ((buf[checksumAt + 1].toInt() and 0xFF) shl 8)
                if (expected != actual) {
                    stats.badCrc++
                    skip()
                    continue
                }
            } else {
                stats.unknownMessages++
            }
            view.fill(
                buffer = buf,
                version = version,
                sequence = buf[start + if (version == 2) 4 else 2].toInt() and 0xFF,
                systemId = buf[start + if (version == 2) 5 else 3].toInt() and 0xFF,
                componentId = buf[start + if (version == 2) 6 else 4].toInt() and 0xFF,
                messageId = messageId,
                payloadOffset = start + headerLength,
                payloadLength = payloadLength,
                incompatFlags = if (version == 2) buf[start + 2].toInt() and 0xFF else 0,
                compatFlags = if (version == 2) buf[start + 3].toInt() and 0xFF else 0,
                signatureOffset = if (signatureLength > 0) checksumAt + FrameLayout.CHECKSUM else -1,
                wireChecksum = (buf[checksumAt].toInt() and 0xFF) or ((buf[checksumAt + 1].toInt() and 0xFF) shl 8),
            )
            head = start + frameLength // before the sink runs, so a throwing sink leaves a consistent state
            stats.frames++
            sink.onFrame(view)
        }
    }

    /** Drops the byte at [head]: garbage, or the magic of a rejected frame. */
    private fun skip() {
        head++
        stats.skippedBytes++
    }

    private companion object {
        /** Room for a full datagram's worth of frames per pass; must exceed [FrameLayout.MAX_FRAME]. */
        const val BUFFER_SIZE = 4096
    }
}

/** Counters of a [FrameDecoder]; plain fields, read them from the decoder's own coroutine or accept slight staleness. */
public class DecoderStats {
    /** Valid frames delivered, including those of unknown message ids. */
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
