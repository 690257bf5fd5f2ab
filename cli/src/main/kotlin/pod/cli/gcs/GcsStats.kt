package pod.cli.gcs

import pod.cli.json.Event
import pod.cli.json.GcsBatch
import java.util.concurrent.atomic.AtomicLong

/**
 * What the server has sent its pages and how they fare, for the benchmark, the tests and
 * `pod gcs` to report: WebSocket messages and their bytes, batches and their sizes, pages open,
 * pages given up on, events dropped for slow pages and requests turned away as busy.
 */
public class GcsStats {
    private val messages = AtomicLong()
    private val bytes = AtomicLong()
    private val batches = AtomicLong()
    private val batchEvents = AtomicLong()
    private val largestBatch = AtomicLong()
    private val open = AtomicLong()
    private val stalls = AtomicLong()
    private val drops = AtomicLong()
    private val busies = AtomicLong()

    /** WebSocket messages sent to every page so far. */
    public val messagesSent: Long get() = messages.get()

    /** Their payload bytes (UTF-8 JSON). */
    public val bytesSent: Long get() = bytes.get()

    /** Batches sent (the other messages are each page's hello). */
    public val batchesSent: Long get() = batches.get()

    /** Events carried by those batches. */
    public val eventsSent: Long get() = batchEvents.get()

    /** The most events one batch carried. */
    public val largestBatchEvents: Long get() = largestBatch.get()

    /** Pages whose WebSocket is open now. */
    public val pagesOpen: Long get() = open.get()

    /** Pages closed because they stopped reading ([PageLimits.sendTimeout]). */
    public val pagesStalled: Long get() = stalls.get()

    /** Events dropped for pages that fell more than [PageLimits.maxEvents] behind. */
    public val eventsDropped: Long get() = drops.get()

    /** Requests answered "busy" ([PageLimits.maxRunning]). */
    public val requestsBusy: Long get() = busies.get()

    internal fun sent(event: Event, size: Int) {
        messages.incrementAndGet()
        bytes.addAndGet(size.toLong())
        if (event is GcsBatch) {
            batches.incrementAndGet()
            batchEvents.addAndGet(event.events.size.toLong())
            largestBatch.accumulateAndGet(event.events.size.toLong(), ::maxOf)
        }
    }

    internal fun pageOpened() {
        open.incrementAndGet()
    }

    internal fun pageClosed() {
        open.decrementAndGet()
    }

    internal fun stalled() {
        stalls.incrementAndGet()
    }

    internal fun dropped() {
        drops.incrementAndGet()
    }

    internal fun busy() {
        busies.incrementAndGet()
    }
}
