package pod.mavlink.signing

/**
 * A link's MAVLink 2 signing policy (set it in [pod.mavlink.GroundStationConfig.signing]). With a
 * policy, the station:
 * - signs every frame it sends with [key] on [linkId], timestamped by a [SigningClock] that reads
 *   [epochMillis];
 * - verifies every signed frame it receives and refuses replays ([ReplayGuard]: per system,
 *   component and link id a timestamp must grow; a new stream at most a minute behind);
 * - refuses unsigned frames unless [acceptUnsigned] is set or [allowUnsigned] lets them through.
 *
 * Refused frames are counted in [pod.mavlink.LinkStats] (badSignatures, replayedFrames,
 * unsignedRefused) and go nowhere else: not routed, not recorded, not acted on.
 *
 * What the other end does (ArduPilot, ArduPilot/ardupilot libraries/GCS_MAVLink/GCS_Signing.cpp,
 * and the MAVLink C library, mavlink_helpers.h `mavlink_signature_check`): once it holds a key it
 * signs everything it sends on every link, and drops unsigned or badly signed frames on every
 * link but channel 0 (USB), except RADIO_STATUS and RADIO; a new stream is accepted at most one
 * minute behind its own timestamp, which it raises to the newest timestamp it verified.
 */
public class LinkSigning(
    /** The 32-byte secret both ends share: frames are signed and checked with it. */
    public val key: SigningKey,
    /** Our link id (0..255) in the frames we sign: one per link, so streams never collide. */
    public val linkId: Int = 0,
    /** Take every unsigned frame (a migration setting: counted, never refused). */
    public val acceptUnsigned: Boolean = false,
    /** Which unsigned frames to take when [acceptUnsigned] is off: by default the radio reports. */
    public val allowUnsigned: UnsignedFilter = UnsignedFilter.RADIO_REPORTS,
    /** Milliseconds since the Unix epoch for signing timestamps: the wall clock by default. */
    public val epochMillis: () -> Long = System::currentTimeMillis,
) {
    init {
        require(linkId in 0..255) { "linkId must be in 0..255, was $linkId" }
    }

    /** Says which link id it signs with, never the key. */
    override fun toString(): String = "LinkSigning(linkId=$linkId, acceptUnsigned=$acceptUnsigned, key=hidden)"
}
