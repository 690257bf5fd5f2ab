package pod.mavlink.signing

import pod.mavlink.LinkStats
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.FrameLayout
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec

/**
 * One link's signing at work under a [LinkSigning] policy: [sign] turns each unsigned MAVLink 2
 * frame the station encodes into a signed one, [admit] decides for each frame received whether
 * it goes on, and counts what it refuses.
 *
 * Verification comes before the replay check, as in the MAVLink C library
 * (`mavlink_signature_check`): a forged frame never touches a stream's last timestamp. (pymavlink's
 * `check_signature` records the timestamp first, so a forged frame with a far-future timestamp
 * would block the real sender's stream there; not here.) Streams are made only by frames with a
 * good signature, so only a key holder can grow the replay table.
 *
 * [admit] runs on the link's receive thread only; [sign] from any thread (the clock is locked).
 */
internal class SignedFrames(private val policy: LinkSigning, private val codec: MessageCodec) {
    private val clock = SigningClock(policy.epochMillis)
    private val guard = ReplayGuard()
    private val encoder = FrameEncoder(codec)

    /** Signed frames whose signature did not verify under the key. */
    @Volatile var badSignatures: Long = 0
        private set

    /** Well-signed frames whose timestamp was not fresh (a replay, or a new stream over a minute old). */
    @Volatile var replayed: Long = 0
        private set

    /** Unsigned frames refused by the policy. */
    @Volatile var unsignedRefused: Long = 0
        private set

    /** Unsigned frames the policy let through ([LinkSigning.acceptUnsigned] or its filter). */
    @Volatile var unsignedAccepted: Long = 0
        private set

    /**
     * [unsigned] (a whole MAVLink 2 frame without a signature, as the encoder writes it) signed:
     * the signed flag set, the CRC recomputed over the new header, the signature block appended.
     * MAVLink 1 frames cannot be signed and are returned as they are.
     */
    fun sign(unsigned: ByteArray): ByteArray {
        if (unsigned[0] != FrameLayout.MAGIC_V2.toByte()) return unsigned
        val crcExtra = codec.crcExtra(FrameSignature.messageId(unsigned)).coerceAtLeast(0)
        return FrameSignature.signUnsigned(unsigned, crcExtra, policy.key, policy.linkId, clock.next())
    }

    /** Whether [frame], just parsed from the link, may be routed; a refused frame is counted. */
    fun admit(frame: MavFrame): Boolean {
        if (frame.signature == null) {
            val allowed = policy.acceptUnsigned || policy.allowUnsigned.allows(frame.messageId, frame.systemId, frame.componentId)
            if (allowed) unsignedAccepted++ else unsignedRefused++
            return allowed
        }
        val bytes = encoder.wireBytes(frame)
        if (!FrameSignature.verify(bytes, policy.key)) {
            badSignatures++
            return false
        }
        val timestamp = FrameSignature.timestamp(bytes)
        if (!guard.accept(frame.systemId, frame.componentId, FrameSignature.linkId(bytes), timestamp, clock.now())) {
            replayed++
            return false
        }
        clock.observe(timestamp)
        return true
    }

    /** [stats] with this link's signing counters. */
    fun countInto(stats: LinkStats): LinkStats =
        stats.copy(badSignatures = badSignatures, replayedFrames = replayed, unsignedRefused = unsignedRefused, unsignedAccepted = unsignedAccepted)
}
