package pod.bench.gcs

import pod.bench.percentile

/** The page's window: the server's CPU and counters over it, and what the browser measured. */
data class PageWindow(val cpu: CpuWindow, val server: ServerCounts, val browser: BrowserWindow)

/** Everything one run of [main] measured, as Markdown for BENCHMARKS.md and as JSON. */
data class GcsResult(val options: GcsOptions, val flying: Int, val framesHeard: Long, val idle: CpuWindow, val page: PageWindow) {
    private val s get() = page.cpu.seconds
    private val frames get() = page.browser.frameMs

    private fun f(x: Double, digits: Int = 1) = "%.${digits}f".format(x)

    private fun pct(x: Double) = f(100 * x) + " %"

    fun markdown(): String = buildString {
        val b = page.browser
        appendLine("== gcs: ${options.vehicles} vehicles (${flying} flying), GLOBAL_POSITION_INT at ${f(options.rate)} Hz, windows of ${f(s)} s")
        appendLine()
        appendLine("| measure | value |")
        appendLine("|---|---:|")
        appendLine("| frame time, p50 / p95 / p99 / max (ms) | ${f(percentile(frames, 50.0))} / ${f(percentile(frames, 95.0))} / ${f(percentile(frames, 99.0))} / ${f(frames.maxOrNull() ?: Double.NaN)} |")
        appendLine("| frames in the window | ${frames.size} (${f(frames.size / b.seconds)} /s) |")
        appendLine("| long tasks (> 50 ms): count, total, max | ${b.longTaskMs.size}, ${f(b.longTaskMs.sum(), 0)} ms, ${f(b.longTaskMs.maxOrNull() ?: 0.0, 0)} ms |")
        appendLine("| batches the page took in | ${b.batches} (${f(b.batches / b.seconds)} /s), ${f(b.events / b.seconds.coerceAtLeast(1e-9), 0)} events/s |")
        appendLine("| JS heap start → end (MB) | ${f(b.heapStartMb)} → ${f(b.heapEndMb)} |")
        appendLine("| WebSocket: messages/s, KB/s | ${f(page.server.messages / s)}, ${f(page.server.bytes / s / 1000)} |")
        appendLine("| events per batch: mean, largest since start | ${f(page.server.events.toDouble() / page.server.batches.coerceAtLeast(1))}, ${page.server.largestBatch} |")
        appendLine("| events dropped for the page | ${page.server.dropped} |")
        appendLine("| server process CPU, no page / page open (share of one core) | ${pct(idle.processShare)} / ${pct(page.cpu.processShare)} |")
        appendLine("| serving one page (difference) | ${pct(page.cpu.processShare - idle.processShare)} |")
        appendLine("| browser (chromium processes) CPU, page open | ${pct(page.cpu.browserShare)} |")
        appendLine("| MAVLink frames the station took in | $framesHeard |")
        appendLine()
        appendLine("Thread groups of the server process, share of one core (no page → page open):")
        for (name in (idle.byThreads.keys + page.cpu.byThreads.keys).sorted()) {
            val a = idle.byThreads[name] ?: 0.0
            val c = page.cpu.byThreads[name] ?: 0.0
            if (a >= 0.002 || c >= 0.002) appendLine("- $name: ${pct(a)} → ${pct(c)}")
        }
    }

    fun json(): String {
        val b = page.browser
        val q = { p: Double -> f(percentile(frames, p), 2) }
        return "{\"vehicles\":${options.vehicles},\"flying\":$flying,\"rate_hz\":${options.rate},\"window_s\":${f(s, 2)}," +
            "\"frame_ms\":{\"p50\":${q(50.0)},\"p95\":${q(95.0)},\"p99\":${q(99.0)},\"max\":${f(frames.maxOrNull() ?: 0.0, 2)},\"count\":${frames.size}}," +
            "\"long_tasks\":{\"count\":${b.longTaskMs.size},\"total_ms\":${f(b.longTaskMs.sum(), 1)}}," +
            "\"page_batches\":${b.batches},\"page_events\":${b.events}," +
            "\"ws\":{\"messages\":${page.server.messages},\"bytes\":${page.server.bytes},\"batches\":${page.server.batches},\"events\":${page.server.events},\"largest_batch\":${page.server.largestBatch},\"dropped\":${page.server.dropped}}," +
            "\"cpu\":{\"idle\":${f(idle.processShare, 4)},\"page\":${f(page.cpu.processShare, 4)},\"browser\":${f(page.cpu.browserShare, 4)}}}"
    }
}
