package pod.mavlink

import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.FrameLayout
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import pod.mavlink.radio.RadioPacer
import pod.mavlink.signing.SignedFrames
import pod.mavlink.tlog.FrameDirection
import pod.mavlink.tlog.FrameTaps

/**
 * The send side of a [GroundStation]: a message becomes a frame with the station's ids and the
 * next sequence number, waits for the radio's pacer when one is active, is signed when the link
 * signs, is shown to the taps and is written to one peer or to all.
 *
 * On a signed link a frame is signed and written in one step, under one lock. A receiver drops a
 * signed frame whose timestamp does not pass the last one it took on that stream, as a replay
 * (MAVLink C library, mavlink_helpers.h `mavlink_signature_check`, which ArduPilot runs; pymavlink's
 * `check_signature` alike), so two senders (the heartbeat loop, a command, an exchange answering
 * on the receive thread) that signed first and wrote second could lose the frame signed earlier:
 * pymavlink counted one such reject in a run of PymavlinkSigningSpec. Links that write in place
 * (UDP) take a plain lock, which the receive thread can take without suspending; the others (TCP,
 * serial) a [Mutex]. Unsigned frames take no lock, as before signing existed.
 */
internal class StationSender(
    private val link: MavlinkLink,
    private val config: GroundStationConfig,
    private val encoder: FrameEncoder,
    private val signing: SignedFrames?,
    private val pacer: RadioPacer,
    private val taps: FrameTaps,
) {
    private val sequences = SequenceNumbers()
    private val signedWrites = Mutex()

    /** Whether [sendNow] may be used: the link writes in place and no radio is pacing the station. */
    val canSendNow: Boolean get() = link.sendsInPlace && !pacer.active

    /**
     * Sends [message] to [peer], or to every peer of the link when it is null; [paced] waits for
     * the radio's pacer first, when one is active (the station's own heartbeat does not: a SiK radio
     * reports on it).
     */
    suspend fun send(message: Any, peer: LinkPeer?, paced: Boolean = true) {
        val unsigned = encode(message)
        if (paced && pacer.active) pacer.pace(unsigned.size + if (signing == null) 0 else FrameLayout.SIGNATURE)
        when {
            signing == null -> write(finish(unsigned), peer)
            link.sendsInPlace -> writeSignedNow(unsigned, peer)
            else -> signedWrites.withLock { write(finish(unsigned), peer) }
        }
    }

    /** Sends [message] to [peer] from the calling thread, without suspending; only while [canSendNow]. */
    fun sendNow(message: Any, peer: LinkPeer) {
        val unsigned = encode(message)
        if (signing == null) link.sendNow(finish(unsigned), peer) else writeSignedNow(unsigned, peer)
    }

    private fun writeSignedNow(unsigned: ByteArray, peer: LinkPeer?) = synchronized(this) {
        val bytes = finish(unsigned)
        if (peer != null) link.sendNow(bytes, peer) else for (each in link.peers) link.sendNow(bytes, each)
    }

    private suspend fun write(bytes: ByteArray, peer: LinkPeer?) {
        if (peer != null) link.send(bytes, peer) else link.sendToAll(bytes)
    }

    private fun encode(message: Any): ByteArray =
        encoder.encode(message, config.systemId, config.componentId, sequences.next(config.systemId, config.componentId), config.mavlinkVersion)

    /** Signs [encoded] when the link signs, and shows the frame to the taps. */
    private fun finish(encoded: ByteArray): ByteArray {
        val bytes = if (signing == null) encoded else signing.sign(encoded)
        if (taps.active) taps.onFrame(FrameDirection.SENT, bytes)
        return bytes
    }
}
