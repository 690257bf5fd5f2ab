package pod.mavlink.codec

/**
 * One MAVLink frame as it travelled on the wire, before (or instead of) decoding its payload.
 *
 * Frames of message ids that Pod cannot decode are still routed as [MavFrame]s, so nothing that a
 * vehicle sends is lost on the way.
 */
public class MavFrame(
    /** 1 for MAVLink 1 (magic 0xFE), 2 for MAVLink 2 (magic 0xFD). */
    public val version: Int,
    /** Sender's packet sequence number, 0..255. */
    public val sequence: Int,
    /** Sender's system id, 0..255. */
    public val systemId: Int,
    /** Sender's component id, 0..255. */
    public val componentId: Int,
    /** Message id: 0..255 in MAVLink 1, 0..16777215 in MAVLink 2. */
    public val messageId: Int,
    /** The payload as on the wire (MAVLink 2 payloads may be truncated of trailing zeros). */
    public val payload: ByteArray,
    /** MAVLink 2 incompatibility flags (0x01: signed). */
    public val incompatFlags: Int = 0,
    /** MAVLink 2 compatibility flags. */
    public val compatFlags: Int = 0,
    /** The 13-byte signature block (link id, 48-bit timestamp, 48-bit signature) or null. */
    public val signature: ByteArray? = null,
) {
    /**
     * The checksum this frame arrived with, or -1 when it was not decoded from the wire: kept so the
     * exact bytes can be written again (a tlog) for message ids whose CRC_EXTRA Pod does not know.
     */
    internal var wireChecksum: Int = -1

    override fun toString(): String =
        "MavFrame(v$version seq=$sequence sys=$systemId comp=$componentId msg=$messageId len=${payload.size})"
}
