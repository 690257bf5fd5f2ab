package pod.bench.tlog

import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.addJsonObject
import kotlinx.serialization.json.buildJsonObject
import kotlinx.serialization.json.put
import kotlinx.serialization.json.putJsonArray
import kotlinx.serialization.json.putJsonObject
import pod.bench.JsonText
import pod.bench.JsonText.num
import pod.bench.percentile
import java.util.Locale
import kotlin.time.Duration

/** The passes of one thing measured; [failure] when it could not run to the end. */
data class TlogCase(
    val key: String,
    val label: String,
    val warmUp: Int,
    val passes: List<Pass>,
    val failure: String? = null,
) {
    val wall: Double get() = percentile(passes.map { it.wallSeconds }, 50.0)
    val cpu: Double get() = percentile(passes.mapNotNull { it.cpuSeconds }, 50.0)
    val recordsPerSecond: Double get() = (passes.firstOrNull()?.records ?: 0) / wall
    val problems: List<String> get() = listOfNotNull(failure) + passes.flatMap { it.problems }.distinct()
    val notes: List<String> get() = passes.flatMap { it.notes }.distinct()
}

/** The tlog benchmark's results as a Markdown table and as JSON. */
object TlogReport {
    fun describe(log: LogContents, o: TlogBenchOptions): String =
        "${o.vehicles} vehicles × ${o.duration}, seed ${o.seed}: ${"%,d".format(Locale.ROOT, log.records)} records, " +
            String.format(Locale.ROOT, "%.1f MB", log.bytes / 1e6) + ", ${fmt(log.logSeconds)} s of log (" +
            log.byMessage.entries.joinToString { "${it.key} ${"%,d".format(Locale.ROOT, it.value)}" } + ")"

    fun markdown(log: LogContents, cases: List<TlogCase>, o: TlogBenchOptions): String = buildString {
        appendLine("Log: ${describe(log, o)}.")
        appendLine()
        appendLine("| pass | runs (+ warm-up) | wall, s: median (min–max) | records/s | MB/s | process CPU, s | checked |")
        appendLine("|---|---:|---:|---:|---:|---:|---|")
        for (c in cases) {
            if (c.passes.isEmpty()) {
                appendLine("| ${c.label} | 0 | – | – | – | – | ✗ ${c.failure} |")
                continue
            }
            val walls = c.passes.map { it.wallSeconds }
            val check = c.problems.takeIf { it.isNotEmpty() }?.let { "✗ " + it.joinToString("; ") } ?: "ok"
            appendLine(
                "| ${c.label} | ${c.passes.size} (+${c.warmUp}) | ${fmt(c.wall)} (${fmt(walls.min())}–${fmt(walls.max())}) | " +
                    "${rate(c.recordsPerSecond)} | ${fmt(log.bytes / 1e6 / c.wall)} | ${fmt(c.cpu)} | $check |",
            )
        }
        val notes = cases.flatMap { c -> c.notes.map { "${c.label}: $it" } }
        if (notes.isNotEmpty()) {
            appendLine()
            notes.forEach { appendLine("- $it") }
        }
        val byKey = cases.filter { it.passes.isNotEmpty() }.associateBy { it.key }
        val pod = byKey["pod-read"]
        val py = byKey["pymavlink-read"]
        appendLine()
        if (pod != null && py != null) {
            appendLine(
                "Read: Pod's TlogTracks.read takes ${ratio(pod.wall, py.wall)} of pymavlink's wall time " +
                    "(${ratio(pod.recordsPerSecond, py.recordsPerSecond)} its records/s) and ${ratio(pod.cpu, py.cpu)} of its CPU time.",
            )
        }
        val ceiling = cases.filter { it.key.startsWith("replay") && it.passes.isNotEmpty() }.maxByOrNull { it.recordsPerSecond }
        if (ceiling != null && pod != null) {
            appendLine(
                "Replay: the fastest replay (${ceiling.label}) delivers ${ratio(ceiling.recordsPerSecond, pod.recordsPerSecond)} " +
                    "the records/s of Pod's read" + (py?.let { ", ${ratio(ceiling.recordsPerSecond, it.recordsPerSecond)} pymavlink's read" } ?: "") +
                    ", at ${ratio(ceiling.cpu, ceiling.wall)} its wall time in process CPU.",
            )
        }
    }

    fun json(log: LogContents, cases: List<TlogCase>, o: TlogBenchOptions, wall: Duration): String = JsonText.pretty.encodeToString(
        JsonElement.serializer(),
        buildJsonObject {
            put("wall_seconds", num(wall.inWholeMilliseconds / 1000.0))
            putJsonObject("log") {
                put("vehicles", o.vehicles)
                put("duration", o.duration.toString())
                put("seed", o.seed)
                put("records", log.records)
                put("bytes", log.bytes)
                put("log_seconds", num(log.logSeconds))
                putJsonObject("by_message") { log.byMessage.forEach { (k, v) -> put(k, v) } }
            }
            putJsonArray("cases") {
                for (c in cases) {
                    addJsonObject {
                        put("key", c.key)
                        put("label", c.label)
                        put("warmup", c.warmUp)
                        put("wall_median_s", num(c.wall))
                        put("cpu_median_s", num(c.cpu))
                        put("records_per_s", num(c.recordsPerSecond))
                        put("mb_per_s", num(log.bytes / 1e6 / c.wall))
                        putJsonArray("wall_s") { c.passes.forEach { add(num(it.wallSeconds)) } }
                        putJsonArray("cpu_s") { c.passes.forEach { add(num(it.cpuSeconds)) } }
                        putJsonArray("problems") { c.problems.forEach { add(JsonPrimitive(it)) } }
                        putJsonArray("notes") { c.notes.forEach { add(JsonPrimitive(it)) } }
                    }
                }
            }
        },
    )

    /** a / b as "0.12×" or "8.3×". */
    private fun ratio(a: Double, b: Double): String = (a / b).let { String.format(Locale.ROOT, if (it < 10) "%.2f×" else "%.1f×", it) }

    private fun rate(perSecond: Double): String = when {
        perSecond >= 1e6 -> String.format(Locale.ROOT, "%.2f M", perSecond / 1e6)
        perSecond >= 1e3 -> String.format(Locale.ROOT, "%.0f k", perSecond / 1e3)
        else -> String.format(Locale.ROOT, "%.0f", perSecond)
    }

    fun fmt(x: Double): String = when {
        !x.isFinite() -> "–"
        x < 1 -> String.format(Locale.ROOT, "%.3f", x)
        x < 100 -> String.format(Locale.ROOT, "%.2f", x)
        else -> String.format(Locale.ROOT, "%.0f", x)
    }
}
