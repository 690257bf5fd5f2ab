package pod.bench.queue

import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.addJsonObject
import kotlinx.serialization.json.buildJsonObject
import kotlinx.serialization.json.put
import kotlinx.serialization.json.putJsonArray
import pod.bench.JsonText
import pod.bench.JsonText.num
import pod.bench.percentile
import java.util.Locale
import kotlin.time.Duration

/** The queue benchmark's results as a Markdown table and as JSON. */
object QueueReport {
    /** "median / p90 ms (ok of all)" of the vehicle-side latency of [runs]. */
    fun cell(runs: List<Change>): String {
        val ok = runs.mapNotNull { it.vehicleMs }
        if (ok.isEmpty()) return "✗ (0 of ${runs.size})"
        val failed = if (ok.size < runs.size) " (${ok.size} of ${runs.size})" else ""
        return String.format(Locale.ROOT, "%s / %s%s", fmt(percentile(ok, 50.0)), fmt(percentile(ok, 90.0)), failed)
    }

    /** One progress line for the runs of one case. */
    fun line(runs: List<Change>): String {
        val first = runs.firstOrNull() ?: return "(no runs)"
        val ground = runs.mapNotNull { it.groundMs }
        val groundText = if (first.method == ChangeMethod.REUPLOAD && ground.isNotEmpty()) ", ground calls returned after ${fmt(percentile(ground, 50.0))} ms (median)" else ""
        return "${first.method.label}, N=${first.size}, ${first.condition.label}: vehicle median / p90 ${cell(runs)} ms$groundText"
    }

    fun markdown(changes: List<Change>, o: QueueBenchOptions): String = buildString {
        val conditions = changes.map { it.condition }.distinct()
        appendLine("Time from the ground's call to the simulated ArduCopter steering for the new point, ms, median / p90")
        appendLine("(${o.reps} changes per cell after ${o.warmUp} not kept; ${o.lossyReps} under loss):")
        appendLine()
        appendLine("| change | N pending | " + conditions.joinToString(" | ") { it.label } + " |")
        appendLine("|---|---:|" + conditions.joinToString("") { "---:|" })
        for ((key, runs) in changes.groupBy { it.method to it.size }) {
            val (method, size) = key
            appendLine("| ${method.label} | $size | " + conditions.joinToString(" | ") { c -> cell(runs.filter { it.condition == c }) } + " |")
        }
    }

    fun json(changes: List<Change>, o: QueueBenchOptions, wall: Duration): String = JsonText.pretty.encodeToString(
        JsonElement.serializer(),
        buildJsonObject {
            put("wall_seconds", num(wall.inWholeMilliseconds / 1000.0))
            put("reps", o.reps)
            put("warmup", o.warmUp)
            put("lossy_reps", o.lossyReps)
            put("gap_ms", o.gap.inWholeMilliseconds)
            putJsonArray("cases") {
                for ((key, runs) in changes.groupBy { Triple(it.method, it.size, it.condition) }) {
                    val ok = runs.mapNotNull { it.vehicleMs }
                    addJsonObject {
                        put("method", key.first.name)
                        put("pending", key.second)
                        put("condition", key.third.name)
                        put("runs", runs.size)
                        put("ok", ok.size)
                        put("vehicle_median_ms", num(percentile(ok, 50.0)))
                        put("vehicle_p90_ms", num(percentile(ok, 90.0)))
                        put("ground_median_ms", num(percentile(runs.mapNotNull { it.groundMs }, 50.0)))
                        putJsonArray("vehicle_ms") { runs.forEach { add(num(it.vehicleMs)) } }
                        putJsonArray("ground_ms") { runs.forEach { add(num(it.groundMs)) } }
                        putJsonArray("errors") { runs.mapNotNull { it.error }.forEach { add(kotlinx.serialization.json.JsonPrimitive(it)) } }
                    }
                }
            }
        },
    )

    private fun fmt(ms: Double): String = when {
        ms < 10 -> String.format(Locale.ROOT, "%.2f", ms)
        ms < 1000 -> String.format(Locale.ROOT, "%.1f", ms)
        else -> String.format(Locale.ROOT, "%.0f", ms)
    }
}
