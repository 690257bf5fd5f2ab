package pod.mavlink

/** Receive-path counters of a [GroundStation]. */
public data class LinkStats(
    /** Valid frames parsed. */
    public val frames: Long = 0,
    /** Frames dropped for a bad CRC. */
    public val badCrc: Long = 0,
    /** Garbage bytes skipped. */
    public val skippedBytes: Long = 0,
    /** Frames of message ids Pod's dialect does not know (routed undecoded). */
    public val unknownMessages: Long = 0,
    /** Frames from systems that never sent a vehicle HEARTBEAT (not routed). */
    public val unrouted: Long = 0,
    /** Frames whose handling failed (nonsense field values); counted and skipped. */
    public val handlerErrors: Long = 0,
    /** Source addresses whose decoder was dropped to stay within [GroundStationConfig.maxPeers]. */
    public val evictedPeers: Long = 0,
    /** Passes of the connection-tracking loop that failed and were skipped (the loop goes on). */
    public val trackingErrors: Long = 0,
    /** Frames whose sender claimed system id 0, the broadcast address (not routed, never a vehicle). */
    public val fromSystemZero: Long = 0,
    /** Frames a recording tap failed on (a tlog that could not be written); see [GroundStation.record]. */
    public val recordingErrors: Long = 0,
    /** Signed frames whose signature did not verify (wrong key, altered bytes); refused ([GroundStationConfig.signing]). */
    public val badSignatures: Long = 0,
    /** Well-signed frames refused as replays: a timestamp not above its stream's last, or a new stream over a minute old. */
    public val replayedFrames: Long = 0,
    /** Unsigned frames a signed link refused (its policy did not allow them). */
    public val unsignedRefused: Long = 0,
    /** Unsigned frames a signed link let through by its policy (radio reports, or all when it accepts unsigned). */
    public val unsignedAccepted: Long = 0,
)
