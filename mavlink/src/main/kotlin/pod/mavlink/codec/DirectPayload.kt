package pod.mavlink.codec

/**
 * A message that writes its own payload, for the few a ground station sends once per item of a
 * transfer (MISSION_ITEM_INT): [FrameEncoder] frames it without the io.dronefleet builder and the
 * generic field-by-field encoder, which box every field through a method handle. The bytes must
 * be those the generic encoder writes for the same message (a test holds each implementation to
 * that), so a receiver cannot tell the two apart.
 */
internal interface DirectPayload {
    /** The MAVLink message id. */
    val messageId: Int

    /** Payload length with extension fields (MAVLink 2, before trailing zeros are trimmed). */
    val length: Int

    /** Payload length without extension fields (MAVLink 1). */
    val baseLength: Int

    /** Writes the full payload ([length] bytes, wire order, little-endian) into [out] from index 0. */
    fun writePayload(out: ByteArray)
}
