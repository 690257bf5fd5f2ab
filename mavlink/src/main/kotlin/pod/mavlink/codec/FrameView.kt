package pod.mavlink.codec

/**
 * A frame a [FrameDecoder] has just checked, read in place from the decoder's buffer: header fields
 * and little-endian payload readers, with no copy. One view per decoder, refilled for every frame
 * and valid only during the sink call it is passed to; [toFrame] copies it out when it must live on.
 *
 * The payload readers zero-extend: a byte at or past [payloadLength] reads as 0, which is how
 * MAVLink 2 senders' truncated trailing zero bytes are to be read (mavlink.io, "Payload
 * truncation"), and how a field the sender's older dialect did not have (an extension) reads.
 */
internal class FrameView {
    var version: Int = 0
        private set
    var sequence: Int = 0
        private set
    var systemId: Int = 0
        private set
    var componentId: Int = 0
        private set
    var messageId: Int = 0
        private set
    var payloadLength: Int = 0
        private set
    private var buffer: ByteArray = EMPTY
    private var payloadOffset = 0
    private var incompatFlags = 0
    private var compatFlags = 0
    private var signatureOffset = -1
    private var wireChecksum = -1

    /** Points this view at a frame in [buffer]: its header fields, where its payload lies, its signature (-1: none). */
    fun fill(
        buffer: ByteArray, version: Int, sequence: Int, systemId: Int, componentId: Int, messageId: Int,
        payloadOffset: Int, payloadLength: Int, incompatFlags: Int, compatFlags: Int, signatureOffset: Int, wireChecksum: Int,
    ) {
        this.buffer = buffer
        this.version = version
        this.sequence = sequence
        this.systemId = systemId
        this.componentId = componentId
        this.messageId = messageId
        this.payloadOffset = payloadOffset
        this.payloadLength = payloadLength
        this.incompatFlags = incompatFlags
        this.compatFlags = compatFlags
        this.signatureOffset = signatureOffset
        this.wireChecksum = wireChecksum
    }

    /** Points this view at [payload] alone (no header): for the payload readers, as in tests of them. */
    fun fillPayload(payload: ByteArray, messageId: Int) {
        fill(payload, 2, 0, 0, 0, messageId, 0, payload.size, 0, 0, -1, -1)
    }

    /** A [MavFrame] of its own: the payload (and signature) copied out of the decoder's buffer. */
    fun toFrame(): MavFrame {
        val frame = MavFrame(
            version = version,
            sequence = sequence,
            systemId = systemId,
            componentId = componentId,
            messageId = messageId,
            payload = buffer.copyOfRange(payloadOffset, payloadOffset + payloadLength),
            incompatFlags = incompatFlags,
            compatFlags = compatFlags,
            signature = if (signatureOffset >= 0) buffer.copyOfRange(signatureOffset, signatureOffset + FrameLayout.SIGNATURE) else null,
        )
        frame.wireChecksum = wireChecksum
        return frame
    }

    /** The payload byte at [index] as 0..255, 0 past the payload's end. */
    fun u8(index: Int): Int = if (index < payloadLength) buffer[payloadOffset + index].toInt() and 0xFF else 0

    /** The signed byte at [index]. */
    fun i8(index: Int): Int = u8(index).toByte().toInt()

    /** The unsigned 16-bit field at [index]. */
    fun u16(index: Int): Int = u8(index) or (u8(index + 1) shl 8)

    /** The signed 16-bit field at [index]. */
    fun i16(index: Int): Int = u16(index).toShort().toInt()

    /** The 32-bit field at [index] as a signed Int (int32_t). */
    fun i32(index: Int): Int =
        if (index + 4 <= payloadLength) {
            buffer.readInt32Le(payloadOffset + index)
        } else {
            u8(index) or (u8(index + 1) shl 8) or (u8(index + 2) shl 16) or (u8(index + 3) shl 24)
        }

    /** The unsigned 32-bit field at [index] (uint32_t). */
    fun u32(index: Int): Long = i32(index).toLong() and 0xFFFF_FFFFL

    /** The float field at [index]. */
    fun f32(index: Int): Float = Float.fromBits(i32(index))

    private companion object {
        val EMPTY = ByteArray(0)
    }
}

/** What a [FrameDecoder] calls for each checked frame, with its one reused [FrameView]. */
internal fun interface FrameViewSink {
    fun onFrame(view: FrameView)
}
