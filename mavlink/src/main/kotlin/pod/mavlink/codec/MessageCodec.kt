package pod.mavlink.codec

/**
 * Payload codec for the io.dronefleet message classes: decodes a frame's payload into a message
 * object and encodes a message object into payload bytes.
 *
 * Each message class is analysed once (wire order, offsets, field kinds) into a plan that is then
 * reused for every frame; io.dronefleet's reflective deserializer is never on the hot path.
 * Thread-safe: one codec (usually [Default]) can serve every link.
 *
 * Two deliberate differences from io.dronefleet's own serializer: uint64 fields decode as
 * non-negative `BigInteger`s (io.dronefleet reads them as signed), and arrays or byte arrays longer
 * than their field make [encodePayload] throw instead of being cut (strings are cut to the field).
 */
public class MessageCodec(dialect: io.dronefleet.mavlink.MavlinkDialect = io.dronefleet.mavlink.ardupilotmega.ArdupilotmegaDialect()) {
    private val catalog = MessageCatalog(dialect)

    /** CRC_EXTRA of [messageId], or -1 when the dialect does not know the message. */
    public fun crcExtra(messageId: Int): Int = catalog.byId(messageId)?.crcExtra ?: -1

    /** The io.dronefleet class of [messageId], or null when the dialect does not know it. */
    public fun messageClass(messageId: Int): Class<*>? = catalog.byId(messageId)?.messageClass

    /** The message id of an io.dronefleet message class; throws IllegalArgumentException otherwise. */
    public fun messageId(messageClass: Class<*>): Int = typeOf(messageClass).id

    /**
     * Decodes [frame]'s payload (zero-extended when truncated), or returns null when the message
     * id is unknown to the dialect.
     */
    public fun decode(frame: MavFrame): Any? = catalog.byId(frame.messageId)?.plan?.decode(frame.payload)

    /** Full-length payload bytes of [message] (an io.dronefleet message object). */
    public fun encodePayload(message: Any): ByteArray = planOf(message.javaClass).encode(message)

    /** The plan of [messageClass]; throws IllegalArgumentException when the dialect does not know it. */
    internal fun planOf(messageClass: Class<*>): MessagePlan = typeOf(messageClass).plan

    /** The plan of message [messageId], or null when the dialect does not know it. */
    internal fun planOf(messageId: Int): MessagePlan? = catalog.byId(messageId)?.plan

    /** Every message class of the dialect, one per id. */
    internal val messageClasses: List<Class<*>> get() = catalog.messageClasses

    private fun typeOf(messageClass: Class<*>): MessageType = catalog.byClass(messageClass)
        ?: throw IllegalArgumentException("${messageClass.name} is not a message of this codec's dialect")

    /** The codec most callers share. */
    public companion object {
        /** A shared codec for the ArduPilotMega dialect (which includes common and minimal). */
        public val Default: MessageCodec by lazy { MessageCodec() }
    }
}
