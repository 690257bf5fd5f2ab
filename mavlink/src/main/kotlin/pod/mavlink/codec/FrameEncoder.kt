package pod.mavlink.codec

/**
 * Serialises messages and frames to wire bytes, byte for byte as pymavlink does (MAVLink 2
 * payloads are truncated of trailing zeros, keeping at least one byte).
 *
 * MAVLink 1 frames carry the base fields only: extension fields do not exist in MAVLink 1, and both
 * pymavlink and the C library leave them out. Thread-safe; holds no state besides its codec.
 */
public class FrameEncoder(private val codec: MessageCodec = MessageCodec.Default) {

    /**
     * Wire bytes of [message] sent as ([systemId], [componentId]) with [sequence], in MAVLink [version] 1 or 2.
     *
     * Throws IllegalArgumentException when [message] is not a message of the codec's dialect, an id
     * is outside 0..255, [version] is neither 1 nor 2, or a MAVLink 1 frame is asked for a message
     * id above 255.
     */
    public fun encode(message: Any, systemId: Int, componentId: Int, sequence: Int, version: Int = 2): ByteArray {
        if (message is DirectPayload) return encodeDirect(message, systemId, componentId, sequence, version)
        val plan = codec.planOf(message.javaClass)
        val payload = plan.encode(message)
        val length = payloadLength(version, plan.id, payload, plan.baseLength) { "message id ${plan.id} (${plan.messageClass.simpleName})" }
        return writeFrame(version, sequence, systemId, componentId, plan.id, payload, length, 0, 0, null, plan.crcExtra)
    }

    /** As [encode], for a message that writes its own payload; its CRC_EXTRA is the codec's for its id. */
    private fun encodeDirect(message: DirectPayload, systemId: Int, componentId: Int, sequence: Int, version: Int): ByteArray {
        val crcExtra = codec.crcExtra(message.messageId)
        require(crcExtra >= 0) { "message id ${message.messageId} is not in the codec's dialect" }
        val payload = ByteArray(message.length)
        message.writePayload(payload)
        val length = payloadLength(version, message.messageId, payload, message.baseLength) { "message id ${message.messageId}" }
        return writeFrame(version, sequence, systemId, componentId, message.messageId, payload, length, 0, 0, null, crcExtra)
    }

    /** How much of [payload] goes on the wire in [version]: trimmed in MAVLink 2, the base fields in MAVLink 1. */
    private inline fun payloadLength(version: Int, id: Int, payload: ByteArray, baseLength: Int, what: () -> String): Int = when (version) {
        2 -> trimmedLength(payload)
        1 -> {
            require(id <= FrameLayout.MAX_V1_MESSAGE_ID) { "MAVLink 1 cannot carry ${what()}, only 0..255" }
            baseLength
        }
        else -> throw IllegalArgumentException("version must be 1 or 2, was $version")
    }

    /**
     * Wire bytes of [frame] exactly as described (payload as given, CRC recomputed).
     *
     * The CRC uses the codec's CRC_EXTRA for the message id, or 0 when the dialect does not know the
     * id: that is what the C library does, so a receiver with the same (unknown to us) message
     * definition rejects the frame either way, while a router that passes unknown ids through
     * unchecked forwards it intact. A MAVLink 2 frame with a [MavFrame.signature] is written with the
     * signed incompatibility flag set and the 13 signature bytes after the CRC (the signature is not
     * recomputed); without one, the signed flag is cleared. Throws IllegalArgumentException for
     * fields out of range, a payload over 255 bytes, a signature that is not 13 bytes, or a MAVLink 1
     * frame with a message id over 255, flags or a signature.
     */
    public fun encode(frame: MavFrame): ByteArray {
        val crcExtra = codec.crcExtra(frame.messageId).let { if (it < 0) 0 else it }
        require(frame.payload.size <= FrameLayout.MAX_PAYLOAD) { "payload must be at most 255 bytes, was ${frame.payload.size}" }
        val signature = frame.signature
        val incompat = when (frame.version) {
            1 -> {
                require(frame.messageId in 0..FrameLayout.MAX_V1_MESSAGE_ID) {
                    "MAVLink 1 message id must be in 0..255, was ${frame.messageId}"
                }
                require(signature == null && frame.incompatFlags == 0 && frame.compatFlags == 0) {
                    "MAVLink 1 frames have no flags and no signature"
                }
                0
            }
            2 -> {
                require(signature == null || signature.size == FrameLayout.SIGNATURE) {
                    "signature must be ${FrameLayout.SIGNATURE} bytes, was ${signature?.size}"
                }
                if (signature != null) frame.incompatFlags or FrameLayout.FLAG_SIGNED else frame.incompatFlags and FrameLayout.FLAG_SIGNED.inv()
            }
            else -> throw IllegalArgumentException("version must be 1 or 2, was ${frame.version}")
        }
        return writeFrame(
            frame.version, frame.sequence, frame.systemId, frame.componentId, frame.messageId,
            frame.payload, frame.payload.size, incompat, frame.compatFlags, signature, crcExtra,
        )
    }

    /**
     * The bytes [frame] had on the wire: [encode] with the checksum it arrived with when it came from
     * a [FrameDecoder] (so frames of unknown message ids come out byte for byte as they came in).
     */
    internal fun wireBytes(frame: MavFrame): ByteArray {
        val bytes = encode(frame)
        val checksum = frame.wireChecksum
        if (checksum >= 0) {
            val at = bytes.size - FrameLayout.CHECKSUM - (frame.signature?.size ?: 0)
            bytes[at] = checksum.toByte()
            bytes[at + 1] = (checksum ushr 8).toByte()
        }
        return bytes
    }

    /** Payload length without trailing zero bytes, but at least 1 (the MAVLink 2 rule). */
    private fun trimmedLength(payload: ByteArray): Int {
        var length = payload.size
        while (length > 1 && payload[length - 1].toInt() == 0) length--
        return length
    }

    private fun writeFrame(
        version: Int,
        sequence: Int,
        systemId: Int,
        componentId: Int,
        messageId: Int,
        payload: ByteArray,
        length: Int,
        incompatFlags: Int,
        compatFlags: Int,
        signature: ByteArray?,
        crcExtra: Int,
    ): ByteArray {
        requireByte("sequence", sequence)
        requireByte("systemId", systemId)
        requireByte("componentId", componentId)
        requireByte("incompatFlags", incompatFlags)
        requireByte("compatFlags", compatFlags)
        require(messageId in 0..FrameLayout.MAX_V2_MESSAGE_ID) { "messageId must be in 0..16777215, was $messageId" }
        val header = if (version == 1) FrameLayout.HEADER_V1 else FrameLayout.HEADER_V2
        val out = ByteArray(header + length + FrameLayout.CHECKSUM + (signature?.size ?: 0))
        var i = 0
        fun put(value: Int) {
            out[i++] = value.toByte()
        }
        if (version == 1) {
            put(FrameLayout.MAGIC_V1); put(length); put(sequence); put(systemId); put(componentId); put(messageId)
        } else {
            put(FrameLayout.MAGIC_V2); put(length); put(incompatFlags); put(compatFlags); put(sequence)
            put(systemId); put(componentId); put(messageId); put(messageId ushr 8); put(messageId ushr 16)
        }
        payload.copyInto(out, i, 0, length)
        i += length
        val crc = Crc.frameChecksum(out, 1, i - 1, crcExtra)
        put(crc)
        put(crc ushr 8)
        signature?.copyInto(out, i)
        return out
    }

    private fun requireByte(name: String, value: Int) =
        require(value in 0..255) { "$name must be in 0..255, was $value" }
}
