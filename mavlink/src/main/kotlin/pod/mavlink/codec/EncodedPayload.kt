package pod.mavlink.codec

/**
 * A message already in its wire form, framed as it is (a [DirectPayload] whose payload is written
 * up front): for the few messages a protocol writes field by field itself (COMMAND_LONG,
 * [pod.mavlink.command.CommandWire]) because the generic path (an io.dronefleet builder, then the
 * message's plan reading each field through a method handle) is most of the cost of sending one,
 * the more so in code the JIT has not compiled yet: a command is sent seldom, so its path is
 * rarely hot. The codec supplies the message's CRC_EXTRA.
 */
internal class EncodedPayload(
    /** The MAVLink message id. */
    override val messageId: Int,
    /** The full-length payload (extension fields included, none trimmed). */
    private val payload: ByteArray,
    /** The length without extension fields: what MAVLink 1 carries. */
    override val baseLength: Int = payload.size,
) : DirectPayload {
    override val length: Int get() = payload.size

    override fun writePayload(out: ByteArray) {
        payload.copyInto(out)
    }
}
