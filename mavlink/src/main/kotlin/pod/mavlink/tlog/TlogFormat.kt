package pod.mavlink.tlog

import pod.mavlink.codec.FrameLayout

/**
 * One tlog record: when a frame was sent or received, and the frame's wire bytes.
 *
 * A tlog (MAVProxy's and pymavlink's telemetry log) is a plain sequence of such records, each an
 * 8-byte big-endian count of microseconds since the Unix epoch followed by exactly one MAVLink 1 or
 * 2 frame, with nothing between records and no file header.
 */
public class TlogRecord(
    /** Microseconds since 1970-01-01T00:00:00Z. */
    public val timestampMicros: Long,
    /** One complete MAVLink frame as on the wire (signature included when signed). */
    public val frame: ByteArray,
) {
    override fun equals(other: Any?): Boolean =
        other is TlogRecord && other.timestampMicros == timestampMicros && other.frame.contentEquals(frame)

    override fun hashCode(): Int = timestampMicros.hashCode() * 31 + frame.contentHashCode()

    override fun toString(): String = "TlogRecord(t=$timestampMicros µs, ${frame.size} bytes)"
}

/** A tlog that cannot be read or written; [message] says where and why. */
public open class TlogException(message: String, cause: Throwable? = null) : pod.core.PodException(message, cause)

/** A tlog that ends inside a record (a recording cut off mid-write). */
public class TlogTruncated(
    /** Byte offset of the incomplete record in the file. */
    public val offset: Long,
    /** Bytes the record needed. */
    public val needed: Int,
    /** Bytes that were there. */
    public val found: Int,
) : TlogException("tlog ends inside the record at byte $offset: it needs $needed bytes, $found are left")

/** Bytes where a tlog record's frame should start that are not a valid MAVLink frame. */
public class TlogCorrupt(
    /** Byte offset of the bad record in the file. */
    public val offset: Long,
    /** What is wrong. */
    public val reason: String,
) : TlogException("tlog record at byte $offset is not a MAVLink frame: $reason")

/** Writing a tlog failed (disk full, stream closed). */
public class TlogWriteFailed(message: String, cause: Throwable? = null) : TlogException(message, cause)

/** Frame lengths from MAVLink headers, shared by the writer's check and the reader. */
internal object TlogFrames {
    /** Bytes of the header needed to know a frame's length: magic, length and (MAVLink 2) incompat flags. */
    const val LENGTH_PREFIX: Int = 3

    const val TIMESTAMP: Int = 8

    /**
     * The total length of the frame whose first [LENGTH_PREFIX] bytes are at [offset] of [bytes],
     * or a reason why they do not start a frame.
     */
    fun lengthOf(bytes: ByteArray, offset: Int): Result {
        val magic = bytes[offset].toInt() and 0xFF
        val payload = bytes[offset + 1].toInt() and 0xFF
        return when (magic) {
            FrameLayout.MAGIC_V1 -> Result.Length(FrameLayout.HEADER_V1 + payload + FrameLayout.CHECKSUM)
            FrameLayout.MAGIC_V2 -> {
                val incompat = bytes[offset + 2].toInt() and 0xFF
                if (incompat and FrameLayout.FLAG_SIGNED.inv() != 0) {
                    Result.NotAFrame("unknown MAVLink 2 incompatibility flags 0x%02x".format(incompat))
                } else {
                    val signature = if (incompat and FrameLayout.FLAG_SIGNED != 0) FrameLayout.SIGNATURE else 0
                    Result.Length(FrameLayout.HEADER_V2 + payload + FrameLayout.CHECKSUM + signature)
                }
            }
            else -> Result.NotAFrame("magic byte 0x%02x is neither 0xFE (MAVLink 1) nor 0xFD (MAVLink 2)".format(magic))
        }
    }

    sealed interface Result {
        class Length(val bytes: Int) : Result
        class NotAFrame(val reason: String) : Result
    }
}
