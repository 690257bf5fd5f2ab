package pod.mavlink.signing

import pod.mavlink.codec.Crc
import pod.mavlink.codec.FrameLayout
import java.security.MessageDigest

/**
 * The MAVLink 2 signature of one frame, as the signing specification defines it: a signed frame
 * has incompatibility flag 0x01 and, after its CRC, 13 bytes — the link id (1), a timestamp (6,
 * little-endian, in 10 µs units since 2015-01-01 00:00 UTC) and the first 6 bytes of
 * SHA-256(key ‖ frame from its magic byte up to and including the timestamp).
 *
 * The CRC covers the header with the flag set but not these 13 bytes, so a frame encoded with
 * the flag and a signature block can be signed after encoding ([sign]).
 */
public object FrameSignature {
    /** Bytes of the hash kept as the signature. */
    public const val LENGTH: Int = 6

    /**
     * Writes into [frame] (a MAVLink 2 frame with the signed flag, ending with its 13-byte signature
     * block) the [linkId], [timestamp] and the signature under [key]; returns [frame].
     */
    public fun sign(frame: ByteArray, key: SigningKey, linkId: Int, timestamp: Long): ByteArray {
        requireSignedFrame(frame)
        require(linkId in 0..255) { "linkId must be 0..255, was $linkId" }
        require(timestamp in 0..MAX_TIMESTAMP) { "timestamp must fit 48 bits, was $timestamp" }
        val block = frame.size - FrameLayout.SIGNATURE
        frame[block] = linkId.toByte()
        for (i in 0 until 6) frame[block + 1 + i] = (timestamp ushr (8 * i)).toByte()
        digest(key, frame).copyInto(frame, frame.size - LENGTH, 0, LENGTH)
        return frame
    }

    /**
     * [unsigned] (a whole MAVLink 2 frame without a signature, as an encoder writes it) as a new
     * signed frame: the signed flag set, the CRC recomputed over that header with [crcExtra] (the
     * message's CRC_EXTRA), the 13-byte block appended and [sign]ed. The caller's array is untouched.
     */
    public fun signUnsigned(unsigned: ByteArray, crcExtra: Int, key: SigningKey, linkId: Int, timestamp: Long): ByteArray {
        require(unsigned.size >= FrameLayout.HEADER_V2 + FrameLayout.CHECKSUM && unsigned[0] == FrameLayout.MAGIC_V2.toByte() &&
            (unsigned[2].toInt() and FrameLayout.FLAG_SIGNED) == 0) { "not an unsigned MAVLink 2 frame" }
        val checksumAt = unsigned.size - FrameLayout.CHECKSUM
        val signed = unsigned.copyOf(unsigned.size + FrameLayout.SIGNATURE)
        signed[2] = (signed[2].toInt() or FrameLayout.FLAG_SIGNED).toByte()
        val crc = Crc.frameChecksum(signed, 1, checksumAt - 1, crcExtra)
        signed[checksumAt] = crc.toByte()
        signed[checksumAt + 1] = (crc ushr 8).toByte()
        return sign(signed, key, linkId, timestamp)
    }

    /** The message id in a MAVLink 2 [frame]'s header. */
    public fun messageId(frame: ByteArray): Int =
        (frame[7].toInt() and 0xFF) or ((frame[8].toInt() and 0xFF) shl 8) or ((frame[9].toInt() and 0xFF) shl 16)

    /** Whether [frame]'s signature is the one [key] gives (constant time in the signature's bytes). */
    public fun verify(frame: ByteArray, key: SigningKey): Boolean {
        if (!isSigned(frame)) return false
        val expected = digest(key, frame)
        var difference = 0
        for (i in 0 until LENGTH) difference = difference or (expected[i].toInt() xor frame[frame.size - LENGTH + i].toInt())
        return difference == 0
    }

    /** The link id of a signed [frame]. */
    public fun linkId(frame: ByteArray): Int = frame[frame.size - FrameLayout.SIGNATURE].toInt() and 0xFF

    /** The timestamp of a signed [frame], in 10 µs units since 2015-01-01 00:00 UTC. */
    public fun timestamp(frame: ByteArray): Long {
        val at = frame.size - FrameLayout.SIGNATURE + 1
        var t = 0L
        for (i in 5 downTo 0) t = (t shl 8) or (frame[at + i].toLong() and 0xFF)
        return t
    }

    /** Whether [frame] is a whole MAVLink 2 frame with the signed flag and its signature block. */
    public fun isSigned(frame: ByteArray): Boolean =
        frame.size >= FrameLayout.HEADER_V2 + FrameLayout.CHECKSUM + FrameLayout.SIGNATURE &&
            frame[0] == FrameLayout.MAGIC_V2.toByte() &&
            (frame[2].toInt() and FrameLayout.FLAG_SIGNED) != 0 &&
            frame.size == FrameLayout.HEADER_V2 + (frame[1].toInt() and 0xFF) + FrameLayout.CHECKSUM + FrameLayout.SIGNATURE

    /** The largest timestamp 48 bits hold. */
    public const val MAX_TIMESTAMP: Long = (1L shl 48) - 1

    private fun requireSignedFrame(frame: ByteArray) =
        require(isSigned(frame)) { "not a MAVLink 2 frame with the signed flag and a 13-byte signature block" }

    private fun digest(key: SigningKey, frame: ByteArray): ByteArray {
        val sha = MessageDigest.getInstance("SHA-256")
        sha.update(key.secret)
        sha.update(frame, 0, frame.size - LENGTH)
        return sha.digest()
    }
}
