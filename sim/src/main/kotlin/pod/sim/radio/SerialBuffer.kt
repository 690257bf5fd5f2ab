package pod.sim.radio

import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import pod.mavlink.link.LinkPeer
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * One radio's buffer between its serial side and the air: bounded to [capacity] bytes (what does
 * not fit is dropped and counted, as SiK does), drained at [bytesPerSecond] by [drain].
 *
 * [offer] may be called from any thread (a UDP link's receive thread); [drain] runs in one coroutine.
 */
internal class SerialBuffer(private val capacity: Int, private val bytesPerSecond: Double, clock: TimeSource) {
    private val started = clock.markNow()
    private val chunks = Channel<Pair<LinkPeer, ByteArray>>(Channel.UNLIMITED)
    private var queued = 0

    /** Bytes dropped because the buffer was full. */
    @Volatile var dropped: Long = 0
        private set

    /** Bytes that crossed. */
    @Volatile var carried: Long = 0
        private set

    /** Takes as much of [bytes] (for [peer]) as fits; the rest is lost. */
    fun offer(peer: LinkPeer, bytes: ByteArray) {
        val taken = synchronized(this) {
            val fits = minOf(bytes.size, capacity - queued)
            dropped += bytes.size - fits
            queued += fits
            fits
        }
        if (taken > 0) chunks.trySend(peer to bytes.copyOf(taken))
    }

    /** Free space in percent, as SiK computes it (in 8-byte steps). */
    fun freePercent(): Int = synchronized(this) { 100 * ((capacity - queued) / 8) / (capacity / 8) }

    /**
     * Hands each chunk to [deliver] once the line has carried its last byte, chunk after chunk at
     * [bytesPerSecond]; until cancelled.
     */
    suspend fun drain(deliver: suspend (LinkPeer, ByteArray) -> Unit) {
        var lineFreeAt = Duration.ZERO
        for ((peer, chunk) in chunks) {
            val now = started.elapsedNow()
            // A chunk taken just after the line came free (a late wake-up: timers round to the
            // millisecond) follows on from the last one, so the rate does not drift below the baud.
            val start = if (now - lineFreeAt < BACK_TO_BACK) lineFreeAt else now
            val done = start + (chunk.size / bytesPerSecond).seconds
            lineFreeAt = done
            if (done > now) delay(done - now)
            synchronized(this) {
                queued -= chunk.size
                carried += chunk.size
            }
            deliver(peer, chunk)
        }
    }

    private companion object {
        val BACK_TO_BACK = 2.milliseconds
    }
}
