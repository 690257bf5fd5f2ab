package pod.cli.gcs

import java.util.concurrent.atomic.AtomicLong

/** What the server has sent its pages, for the benchmark and for `pod gcs` to report: WebSocket messages and their bytes. */
public class GcsStats {
    private val messages = AtomicLong()
    private val bytes = AtomicLong()

    /** WebSocket messages sent to every page so far. */
    public val messagesSent: Long get() = messages.get()

    /** Their payload bytes (UTF-8 JSON). */
    public val bytesSent: Long get() = bytes.get()

    internal fun sent(size: Int) {
        messages.incrementAndGet()
        bytes.addAndGet(size.toLong())
    }
}
