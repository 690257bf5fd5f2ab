package pod.mavlink.tlog

/** Which way a frame went through a ground station's link. */
public enum class FrameDirection {
    /** Received from a peer. */
    RECEIVED,

    /** Sent by the station. */
    SENT,
}

/**
 * Sees every frame a [pod.mavlink.GroundStation] sends and receives, with its time: see
 * [pod.mavlink.GroundStation.record]. Called on the station's receive thread and on its senders'
 * threads, possibly at once: it must be thread-safe and must not block for long. What it throws
 * is counted in [pod.mavlink.LinkStats.recordingErrors], never passed to the station.
 */
public fun interface FrameTap {
    /** [frame] (one complete frame's wire bytes) went [direction] at [timestampMicros] since the Unix epoch. */
    public fun onFrame(timestampMicros: Long, direction: FrameDirection, frame: ByteArray)
}

/**
 * A recording in progress. After [stop] no new frame goes to the tap; one that another thread was
 * handing over at that moment may still arrive, so close a writer after stop (its late write then
 * fails and is counted, see [FrameTap]).
 */
public fun interface Recording : AutoCloseable {
    /** Ends the recording: frames after this call are not passed to the tap. Safe to call twice. */
    public fun stop()

    /** Same as [stop]. */
    override fun close(): Unit = stop()
}
