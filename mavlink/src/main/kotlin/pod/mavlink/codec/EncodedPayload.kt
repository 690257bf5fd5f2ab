package pod.mavlink.codec

/**
 * A message already in its wire form, which [FrameEncoder.encode] frames as it is: for the few
 * messages a protocol writes field by field itself (COMMAND_LONG, [pod.mavlink.command.CommandWire])
 * because the generic path (an io.dronefleet builder, then the message's plan reading each field
 * through a method handle) is most of the cost of sending one, the more so in code the JIT has not
 * compiled yet: a command is sent seldom, so its path is rarely hot.
 */
internal class EncodedPayload(
    /** The MAVLink message id. */
    val messageId: Int,
    /** The message's CRC_EXTRA. */
    val crcExtra: Int,
    /** The full-length payload (extension fields included, none trimmed). */
    val payload: ByteArray,
    /** The length without extension fields: what MAVLink 1 carries. */
    val baseLength: Int = payload.size,
)
