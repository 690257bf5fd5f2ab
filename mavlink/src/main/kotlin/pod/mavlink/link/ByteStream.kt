package pod.mavlink.link

import java.io.IOException
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * One open byte stream under a [StreamLink]: a TCP connection or a serial port. It has no notion
 * of frames (the station's [pod.mavlink.codec.FrameDecoder] finds them in whatever chunks arrive)
 * nor of reopening (the link does that, with a fresh stream).
 */
internal interface ByteStream {
    /**
     * Reads what has arrived into [buffer], waiting for at least one byte: the count, or -1 when the
     * stream ended (the remote hung up, the device went away). Throws [IOException] when it broke.
     */
    suspend fun read(buffer: ByteArray): Int

    /**
     * Writes [bytes]; returns how many went out, fewer than all when a bounded write timed out (a
     * peer that reads nothing). Throws [IOException] when the stream broke.
     */
    suspend fun write(bytes: ByteArray): Int

    /** Closes the stream; a [read] in progress returns or throws. */
    fun close()

    /** Suspends until what [close] started has released the stream's resources. */
    suspend fun awaitClosed() {}
}

/**
 * How a [StreamLink] opens its address again after the stream went down: [open] every [first] at
 * first, the wait doubling up to [longest], until it succeeds or the link is closed.
 */
internal class Reopening(
    val open: suspend () -> ByteStream,
    val first: Duration = 250.milliseconds,
    val longest: Duration = 1.seconds,
)
