package pod.mavlink.codec

/**
 * Payload codec for the io.dronefleet message classes: decodes a frame's payload into a message
 * object and encodes a message object into payload bytes.
 *
 * Each message class is analysed once (wire order, offsets, field kinds) into a plan that is then
 * reused for every frame; io.dronefleet's reflective deserializer is never on the hot path.
 */
public class MessageCodec(dialect: io.dronefleet.mavlink.MavlinkDialect = io.dronefleet.mavlink.ardupilotmega.ArdupilotmegaDialect()) {

    /** CRC_EXTRA of [messageId], or -1 when the dialect does not know the message. */
    public fun crcExtra(messageId: Int): Int = TODO()

    /** The io.dronefleet class of [messageId], or null when the dialect does not know it. */
    public fun messageClass(messageId: Int): Class<*>? = TODO()

    /** The message id of an io.dronefleet message class; throws IllegalArgumentException otherwise. */
    public fun messageId(messageClass: Class<*>): Int = TODO()

    /**
     * Decodes [frame]'s payload (zero-extended when truncated), or returns null when the message
     * id is unknown to the dialect.
     */
    public fun decode(frame: MavFrame): Any? = TODO()

    /** Full-length payload bytes of [message] (an io.dronefleet message object). */
    public fun encodePayload(message: Any): ByteArray = TODO()

    public companion object {
        /** A shared codec for the ArduPilotMega dialect (which includes common and minimal). */
        public val Default: MessageCodec by lazy { MessageCodec() }
    }
}
