package pod.mavlink.tlog

import kotlinx.coroutines.CancellableContinuation
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.Delay
import kotlinx.coroutines.DisposableHandle
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.InternalCoroutinesApi
import java.util.PriorityQueue
import kotlin.coroutines.CoroutineContext
import kotlin.time.AbstractLongTimeSource
import kotlin.time.DurationUnit
import kotlin.time.TimeSource

/**
 * A replay's time: the log's own clock, and a dispatcher whose delays and timeouts follow it.
 *
 * Coroutines run on [delegate]; a `delay` or `withTimeout` on this dispatcher waits for log time,
 * which only [advanceTo] moves. [advanceTo] first runs every timer due up to the new time, in order
 * of due time, in place on the caller's thread and with the clock reading each timer's own due
 * time, so that what a ground station does on a timer (checking its vehicles' silence) happens
 * between the records it falls between, at any speed, however late the process plays a record.
 *
 * kotlinx.coroutines lets a dispatcher carry its own clock only through [Delay], its internal API:
 * the same seam kotlinx-coroutines-test's dispatchers use for virtual time.
 */
@OptIn(InternalCoroutinesApi::class)
internal class LogTimeline(private val delegate: CoroutineDispatcher) : CoroutineDispatcher(), Delay {
    @Volatile private var nowMicros: Long = 0
    private val timers = PriorityQueue<Timer>()
    private var scheduled = 0L

    /** Log time in microseconds from the first record: what [clock] reads. */
    val micros: Long get() = nowMicros

    /** The log's time as a clock. */
    val clock: TimeSource.WithComparableMarks = object : AbstractLongTimeSource(DurationUnit.MICROSECONDS) {
        override fun read(): Long = nowMicros
    }

    override fun isDispatchNeeded(context: CoroutineContext): Boolean = delegate.isDispatchNeeded(context)

    override fun dispatch(context: CoroutineContext, block: Runnable) = delegate.dispatch(context, block)

    @OptIn(ExperimentalCoroutinesApi::class)
    override fun scheduleResumeAfterDelay(timeMillis: Long, continuation: CancellableContinuation<Unit>) {
        val timer = schedule(timeMillis) { with(continuation) { this@LogTimeline.resumeUndispatched(Unit) } }
        continuation.invokeOnCancellation { timer.dispose() }
    }

    override fun invokeOnTimeout(timeMillis: Long, block: Runnable, context: CoroutineContext): DisposableHandle =
        schedule(timeMillis) { block.run() }

    /**
     * Moves log time forward to [micros] (never back), running each timer due by then at its own
     * due time first.
     */
    fun advanceTo(micros: Long) {
        while (true) {
            val due = synchronized(timers) {
                val head = timers.peek()
                if (head == null || head.dueMicros > micros) null else timers.poll()
            } ?: break
            if (due.disposed) continue
            if (due.dueMicros > nowMicros) nowMicros = due.dueMicros
            due.action()
        }
        if (micros > nowMicros) nowMicros = micros
    }

    private fun schedule(timeMillis: Long, action: () -> Unit): Timer = synchronized(timers) {
        val delayMicros = if (timeMillis >= Long.MAX_VALUE / 1000) Long.MAX_VALUE / 2 else timeMillis.coerceAtLeast(0) * 1000
        Timer(nowMicros + delayMicros, scheduled++, action).also { timers.add(it) }
    }

    private class Timer(val dueMicros: Long, val order: Long, val action: () -> Unit) : Comparable<Timer>, DisposableHandle {
        @Volatile var disposed = false

        override fun dispose() {
            disposed = true
        }

        override fun compareTo(other: Timer): Int =
            if (dueMicros != other.dueMicros) dueMicros.compareTo(other.dueMicros) else order.compareTo(other.order)
    }

    override fun toString(): String = "LogTimeline(at ${nowMicros} µs of log, on $delegate)"
}
