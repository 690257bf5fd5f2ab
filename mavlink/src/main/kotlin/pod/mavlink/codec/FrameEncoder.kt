package pod.mavlink.codec

/**
 * Serialises messages and frames to wire bytes, byte for byte as pymavlink does (MAVLink 2
 * payloads are truncated of trailing zeros, keeping at least one byte).
 */
public class FrameEncoder(private val codec: MessageCodec = MessageCodec.Default) {

    /** Wire bytes of [message] sent as ([systemId], [componentId]) with [sequence], in MAVLink [version] 1 or 2. */
    public fun encode(message: Any, systemId: Int, componentId: Int, sequence: Int, version: Int = 2): ByteArray = TODO()

    /** Wire bytes of [frame] exactly as described (payload as given, CRC recomputed). */
    public fun encode(frame: MavFrame): ByteArray = TODO()
}
