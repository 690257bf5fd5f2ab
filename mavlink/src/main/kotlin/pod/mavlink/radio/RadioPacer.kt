package pod.mavlink.radio

import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.TimeSource

/**
 * The station's send-side pacing (see [RadioPacing]): off, at the cost of one volatile read per
 * send, until a RADIO_STATUS is heard; from then on every send reserves its bytes from a token
 * bucket and waits, on the caller's coroutine, until they are due.
 *
 * Reservations are taken in call order and each waits for its own due time, so concurrent senders
 * leave in the order they asked, at the paced rate between them.
 */
internal class RadioPacer(private val pacing: RadioPacing, clock: TimeSource) {
    private val started = clock.markNow()
    private val _status = MutableStateFlow<RadioStatus?>(null)

    /** The latest report heard, or null. */
    val status: StateFlow<RadioStatus?> = _status.asStateFlow()

    /** Whether sends are paced now: pacing is enabled and a radio has reported. */
    @Volatile var active: Boolean = false
        private set

    /** Bytes per second allowed now (the initial rate until a report moves it). */
    @Volatile var rate: Int = pacing.initialRate
        private set

    private var tokens = pacing.burst.toDouble()
    private var filledAt = 0L

    /** A report was heard (on the receive path): remember it and move the rate by its `txbuf`. */
    fun onReport(report: RadioStatus) {
        _status.value = report
        if (!pacing.enabled) return
        synchronized(this) {
            if (!active) {
                filledAt = nowNanos()
                active = true
                return // the first report starts pacing at the initial rate
            }
            refill()
            val free = report.txbuf
            rate = when {
                free < pacing.criticalBelow -> rate / 2
                free < pacing.lowBelow -> rate - rate / 4
                free > pacing.emptyAbove -> rate + 2 * pacing.increase
                free > pacing.roomyAbove -> rate + pacing.increase
                else -> rate
            }.coerceIn(pacing.minRate, pacing.maxRate)
        }
    }

    /** Waits until [bytes] more may go out; returns at once while pacing is off. */
    suspend fun pace(bytes: Int) {
        if (!active) return
        val waitNanos = synchronized(this) {
            refill()
            tokens -= bytes
            if (tokens >= 0) 0L else (-tokens * NANOS_PER_SECOND / rate).toLong()
        }
        if (waitNanos > 0) delay(waitNanos.nanoseconds)
    }

    /**
     * The shortest a protocol's resend timeout should be now: the time two of the longest frames
     * take at the paced rate (0 while nothing is paced). Over a radio, an answer queued behind a
     * telemetry frame or two comes tens of milliseconds late; a loopback-sized timeout (10 ms)
     * then resends items that were never lost, and the resends queue ahead of the next answer: a
     * 200-item upload through an emulated 57600-baud pair carried 2.8× the bytes it needed and took
     * 2.3× pymavlink's time (BENCHMARKS.md, "Mission upload over a 57600-baud radio").
     */
    fun resendFloorNanos(): Long = if (!active) 0L else (FLOOR_FRAMES * MAX_FRAME_BYTES * NANOS_PER_SECOND / rate).toLong()

    private fun refill() {
        val now = nowNanos()
        tokens = minOf(pacing.burst.toDouble(), tokens + (now - filledAt) * rate / NANOS_PER_SECOND)
        filledAt = now
    }

    private fun nowNanos(): Long = started.elapsedNow().inWholeNanoseconds

    private companion object {
        const val NANOS_PER_SECOND = 1e9

        /** A MAVLink 2 frame's most bytes: header 10, payload 255, checksum 2, signature 13. */
        const val MAX_FRAME_BYTES = 280

        /** How many of the longest frames the floor waits for. */
        const val FLOOR_FRAMES = 2
    }
}
