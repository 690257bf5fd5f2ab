package pod.mavlink.link

import kotlinx.coroutines.flow.StateFlow

/** Whether a [ByteStreamLink]'s device or connection is there. */
public sealed class LinkState {
    /** Open: bytes flow both ways. */
    public data object Up : LinkState()

    /**
     * Gone ([reason]: the device disappeared, the server hung up). A link that [reopens] tries the
     * same address again until it is back or closed; sends meanwhile are dropped and counted.
     */
    public data class Down(
        /** What the link saw, e.g. "serial link on /dev/ttyUSB0 lost its device". */
        public val reason: String,
        /** Whether the link is trying to reopen by itself. */
        public val reopens: Boolean,
        /** Attempts to reopen that failed so far in this outage (the device still missing). */
        public val failedReopens: Int = 0,
    ) : LinkState()

    /** Closed by its owner; nothing more happens. */
    public data object Closed : LinkState()
}

/** What a [ByteStreamLink] has counted since it was opened. */
public data class StreamCounters(
    /** Bytes read from the stream. */
    public val bytesReceived: Long = 0,
    /** Bytes written to the stream. */
    public val bytesSent: Long = 0,
    /** Times the stream went down (a device unplugged, a server hanging up). */
    public val outages: Long = 0,
    /** Times it was opened again after going down. */
    public val reopens: Long = 0,
    /** Failed attempts to open it again (the device still missing). */
    public val failedReopens: Long = 0,
    /** Sends dropped, whole or in part, because the stream was down or a write timed out. */
    public val droppedSends: Long = 0,
    /** Bytes of those dropped sends that never went out. */
    public val droppedBytes: Long = 0,
)

/**
 * A link over one byte stream, a TCP connection or a serial port, which says whether it is up. A
 * serial link ([LinkAddress.Serial]) reopens its device by itself after it disappears (a USB radio
 * unplugged and plugged back); a TCP link reports the hang-up and stays down.
 */
public interface ByteStreamLink : MavlinkLink {
    /** Up, down (and why), or closed, as it changes. */
    public val state: StateFlow<LinkState>

    /** A snapshot of what the link has counted so far. */
    public val counters: StreamCounters
}
