package pod.sim.signing

import io.dronefleet.mavlink.common.SetupSigning
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec
import pod.mavlink.signing.FrameSignature
import pod.mavlink.signing.SigningClock
import pod.mavlink.signing.SigningKey
import pod.mavlink.signing.UnsignedFilter

/**
 * A simulated vehicle's MAVLink 2 signing, as ArduPilot does it (ArduPilot/ardupilot
 * libraries/GCS_MAVLink/GCS_Signing.cpp, with the MAVLink C library's `mavlink_signature_check`
 * and `mavlink_sign_packet` in mavlink_helpers.h):
 * - No key: nothing is checked or signed.
 * - SETUP_SIGNING (id 256; handled in GCS_Common.cpp `handle_common_message` for the system it
 *   targets, routing drops the others) is refused while armed ("ERROR: Won't setup signing when
 *   armed", `handle_setup_signing`); otherwise the key and `initial_timestamp` are stored and used
 *   at once on every link. A key of 32 zero bytes with timestamp 0 turns signing off
 *   (`load_signing_key`: "if timestamp and key are all zero then we disable signing").
 * - The stored timestamp is saved every 30 s and at GPS lock (`save_signing_timestamp`); a key
 *   loaded from storage starts one minute past it, so frames sent before a reboot cannot be
 *   replayed after it. At GPS lock the timestamp is raised to GPS time (`update_signing_timestamp`);
 *   here the simulated GPS has its fix from boot, so a key from the vehicle's config starts at
 *   the wall clock read through [epochMillis].
 * - Outgoing: once keyed, every frame it sends is signed on its link id (the channel number, 1
 *   for this telemetry link), with the current timestamp, which then grows by one
 *   (`mavlink_sign_packet`).
 * - Incoming: a signed frame must verify; then per (system, component, link id) its timestamp must
 *   exceed the stream's last, and a new stream may be at most a minute behind our timestamp, with
 *   at most 16 streams (MAVLINK_MAX_SIGNING_STREAMS). A verified frame raises our timestamp to its
 *   own. Unsigned or badly signed frames are dropped silently, as a parse error, except RADIO_STATUS
 *   and RADIO (`accept_unsigned_callback`'s list). ArduPilot also accepts anything on channel 0
 *   (USB, "assumed to be secure"); this simulated link is a telemetry link, not channel 0.
 *
 * Every method is synchronized: frames arrive on the link's thread, sends leave from the vehicle's.
 */
internal class ArduPilotSigning(
    initialKey: SigningKey?,
    private val codec: MessageCodec,
    private val epochMillis: () -> Long = System::currentTimeMillis,
) {
    private val encoder = FrameEncoder(codec)
    private var key: SigningKey? = initialKey
    private var timestamp: Long = if (initialKey != null) SigningClock.fromEpochMillis(epochMillis()) else 0
    private val streams = LinkedHashMap<Int, Long>()

    /** Frames dropped for a missing or bad signature or a stale timestamp. */
    @Volatile var refused: Long = 0
        private set

    /** Whether a key is set. */
    val enabled: Boolean @Synchronized get() = key != null

    /** Whether [frame] may be handled. */
    @Synchronized
    fun admits(frame: MavFrame): Boolean {
        val key = key ?: return true
        val ok = frame.signature != null && verified(frame, key)
        if (ok || frame.messageId == UnsignedFilter.RADIO_STATUS || frame.messageId == UnsignedFilter.RADIO) return true
        refused++
        return false
    }

    private fun verified(frame: MavFrame, key: SigningKey): Boolean {
        val bytes = encoder.encode(frame)
        if (!FrameSignature.verify(bytes, key)) return false
        val t = FrameSignature.timestamp(bytes)
        val stream = (frame.systemId shl 16) or (frame.componentId shl 8) or FrameSignature.linkId(bytes)
        val last = streams[stream]
        if (last == null) {
            if (streams.size >= MAX_STREAMS || t + NEW_STREAM_WINDOW < timestamp) return false
        } else if (t <= last) {
            return false
        }
        streams[stream] = t
        if (t > timestamp) timestamp = t
        return true
    }

    /** [unsigned] (a MAVLink 2 frame the vehicle encoded) signed when a key is set, else as it is. */
    @Synchronized
    fun sign(unsigned: ByteArray): ByteArray {
        val key = key ?: return unsigned
        val crcExtra = codec.crcExtra(FrameSignature.messageId(unsigned)).coerceAtLeast(0)
        return FrameSignature.signUnsigned(unsigned, crcExtra, key, LINK_ID, timestamp++)
    }

    /** Handles SETUP_SIGNING; returns the STATUSTEXT of a refusal, or null when done. */
    @Synchronized
    fun setup(message: SetupSigning, armed: Boolean): String? {
        if (armed) return "ERROR: Won't setup signing when armed"
        val secret = message.secretKey() ?: ByteArray(0)
        val initial = message.initialTimestamp()?.toLong() ?: 0L
        if (secret.size != SigningKey.SIZE) return "ERROR: Failed to save signing key"
        if (initial == 0L && secret.all { it.toInt() == 0 }) {
            key = null
            streams.clear()
            return null
        }
        key = SigningKey(secret)
        // load_signing_key: "use a timestamp 1 minute past the last recorded timestamp".
        timestamp = initial + NEW_STREAM_WINDOW
        return null
    }

    companion object {
        /** The link id it signs with: ArduPilot uses the channel number; a telemetry link is channel 1. */
        const val LINK_ID: Int = 1

        /** MAVLINK_MAX_SIGNING_STREAMS of the C library. */
        const val MAX_STREAMS: Int = 16

        /** One minute in 10 µs units (MAVLINK_SIGNING_TIMESTAMP_LIMIT 60 s × 100,000). */
        const val NEW_STREAM_WINDOW: Long = 6_000_000
    }
}
