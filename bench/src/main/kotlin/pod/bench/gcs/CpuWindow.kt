package pod.bench.gcs

import kotlinx.coroutines.delay
import java.lang.management.ManagementFactory
import kotlin.time.Duration
import kotlin.time.TimeSource

/**
 * CPU used over one measured window: this process's (as a share of one core), each thread group's
 * of it (by thread name: the server's, the station's, the coroutines') and the browser's processes
 * (chromium, a descendant of this JVM through chromedriver).
 */
data class CpuWindow(val seconds: Double, val processShare: Double, val byThreads: Map<String, Double>, val browserShare: Double) {
    companion object {
        /** Runs [start], then measures for [window]. */
        suspend fun measure(window: Duration, start: () -> Unit = {}): CpuWindow {
            start()
            val os = ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean
            val cpu0 = os.processCpuTime
            val threads0 = threadCpu()
            val browser0 = browserCpuNanos()
            val t0 = TimeSource.Monotonic.markNow()
            delay(window)
            val wall = t0.elapsedNow().inWholeNanoseconds.toDouble()
            val threads1 = threadCpu()
            val groups = HashMap<String, Double>()
            for ((id, end) in threads1) {
                val (name, nanos) = end
                val spent = nanos - (threads0[id]?.second ?: 0L)
                groups.merge(group(name), spent / wall, Double::plus)
            }
            return CpuWindow(wall / 1e9, (os.processCpuTime - cpu0) / wall, groups.toSortedMap(), (browserCpuNanos() - browser0) / wall)
        }

        private fun threadCpu(): Map<Long, Pair<String, Long>> {
            val mx = ManagementFactory.getThreadMXBean()
            return mx.allThreadIds.toList().mapNotNull { id ->
                val info = mx.getThreadInfo(id) ?: return@mapNotNull null
                val nanos = mx.getThreadCpuTime(id).takeIf { it >= 0 } ?: return@mapNotNull null
                id to (info.threadName to nanos)
            }.toMap()
        }

        /** Thread names without their numbers: `ktor-cio-dispatcher-worker-3` → `ktor-cio-dispatcher-worker`. */
        private fun group(name: String): String = name.replace(Regex("""[-#@ ]?\d+$"""), "").replace(Regex("""\d+"""), "N")

        private fun browserCpuNanos(): Long = ProcessHandle.current().descendants()
            .filter { p -> p.info().command().map { "chrom" in it }.orElse(false) }
            .mapToLong { p -> p.info().totalCpuDuration().map { it.toNanos() }.orElse(0L) }
            .sum()
    }
}

/** The server's counters ([pod.cli.gcs.GcsStats]) at one moment, and the difference of two. */
data class ServerCounts(val messages: Long, val bytes: Long, val batches: Long, val events: Long, val largestBatch: Long, val dropped: Long) {
    operator fun minus(o: ServerCounts) = ServerCounts(messages - o.messages, bytes - o.bytes, batches - o.batches, events - o.events, largestBatch, dropped - o.dropped)

    companion object {
        fun of(s: pod.cli.gcs.GcsStats) = ServerCounts(s.messagesSent, s.bytesSent, s.batchesSent, s.eventsSent, s.largestBatchEvents, s.eventsDropped)
    }
}
