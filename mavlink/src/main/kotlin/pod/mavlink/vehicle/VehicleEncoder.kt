package pod.mavlink.vehicle

import pod.mavlink.SequenceNumbers
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec

/**
 * Wire bytes of what one vehicle component sends, as ([systemId], [componentId]), its frames
 * numbered in the order they are encoded (0..255, then round again), as a receiver counting lost
 * frames expects. Thread-safe.
 */
public class VehicleEncoder(
    /** Encodes the payloads: the dialect the vehicle speaks. */
    codec: MessageCodec = MessageCodec.Default,
    /** The vehicle's MAVLink system id. */
    public val systemId: Int,
    /** The sending component's id. */
    public val componentId: Int,
) {
    private val encoder = FrameEncoder(codec)
    private val sequences = SequenceNumbers()

    /** The MAVLink 2 frame of [message] (an io.dronefleet message object), with the next sequence number. */
    public fun encode(message: Any): ByteArray = encoder.encode(message, systemId, componentId, sequences.next(systemId, componentId))
}
