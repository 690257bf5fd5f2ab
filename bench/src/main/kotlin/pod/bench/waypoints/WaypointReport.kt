package pod.bench.waypoints

import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.addJsonObject
import kotlinx.serialization.json.buildJsonObject
import kotlinx.serialization.json.put
import kotlinx.serialization.json.putJsonArray
import pod.bench.JsonText
import pod.bench.JsonText.num
import pod.bench.percentile
import java.util.Locale
import kotlin.time.Duration

/** The waypoint benchmark's results as a Markdown table and as JSON; all times vehicle seconds. */
object WaypointReport {
    /** Figures of one mechanism's flights (all reps pooled). */
    private class Summary(flights: List<Flight>, val reference: Double?, o: WaypointBenchOptions) {
        val ok = flights.mapNotNull { it.timings }
        val failed = flights.size - ok.size
        private val stops = ok.flatMap { it.waypoints }
        val before = stops.mapNotNull { it.before }
        val after = stops.mapNotNull { it.after }
        val overhead = stops.mapNotNull { w -> w.before?.let { b -> w.after?.let { a -> a + b } } }
        val offsets = stops.mapNotNull { it.offsetAtAction }
        val neverWithin = stops.count { it.actionStart != null && it.arrived == null }
        val total = ok.mapNotNull { it.total }.takeIf { it.isNotEmpty() }?.let { percentile(it, 50.0) }

        /** (total − reference − N × action) ÷ N: what stopping costs per waypoint beyond the action itself. */
        val excessPerWaypoint: Double? = if (total != null && reference != null && stops.any { it.actionStart != null }) {
            (total - reference - o.waypoints * o.action.seconds()) / o.waypoints
        } else {
            null
        }
    }

    /** One progress line for a flight. */
    fun line(f: Flight, o: WaypointBenchOptions): String {
        val t = f.timings ?: return "${f.mechanism.label}: FAILED ${f.error}"
        val s = Summary(listOf(f), null, o)
        return "${f.mechanism.label}: total ${fmt(t.total)} s, arrival→action ${medMax(s.before)}, action→moving ${medMax(s.after)}, " +
            "offset at action ${medMax(s.offsets)} m" + if (s.neverWithin > 0) ", ${s.neverWithin} never within 1 m" else ""
    }

    fun markdown(flights: List<Flight>, o: WaypointBenchOptions): String = buildString {
        appendLine("${o.waypoints} waypoints ${fmt(o.spacing)} m apart in a line at ${fmt(o.height)} m, a ${o.action} action at each; vehicle seconds, median / max over the waypoints of ${o.reps} flight(s) each:")
        appendLine()
        appendLine("| autopilot | link | mechanism | arrival (1 m) → action start | action end → moving on | overhead per waypoint | distance from waypoint during action, m | total, s | beyond the actions and the non-stop path, per waypoint |")
        appendLine("|---|---|---|---:|---:|---:|---:|---:|---:|")
        for ((key, group) in flights.groupBy { it.autopilot to it.condition }) {
            val reference = group.filter { it.mechanism == Mechanism.NONSTOP }.mapNotNull { it.timings?.total }.takeIf { it.isNotEmpty() }?.let { percentile(it, 50.0) }
            for ((mechanism, runs) in group.groupBy { it.mechanism }) {
                val s = Summary(runs, reference, o)
                val failed = if (s.failed > 0) " (${s.failed} of ${runs.size} failed: ${runs.mapNotNull { it.error }.distinct().joinToString()})" else ""
                val never = if (s.neverWithin > 0) " (${s.neverWithin} never within 1 m)" else ""
                if (mechanism == Mechanism.NONSTOP) {
                    appendLine("| ${key.first} | ${key.second.label} | ${mechanism.label}$failed | – | – | – | – | ${fmt(s.total)} | – |")
                } else {
                    appendLine(
                        "| ${key.first} | ${key.second.label} | ${mechanism.label}$failed | ${medMax(s.before)}$never | ${medMax(s.after)} | ${medMax(s.overhead)} | " +
                            "${medMax(s.offsets)} | ${fmt(s.total)} | ${fmt(s.excessPerWaypoint)} |",
                    )
                }
            }
        }
    }

    fun json(flights: List<Flight>, o: WaypointBenchOptions, wall: Duration): String = JsonText.pretty.encodeToString(
        JsonElement.serializer(),
        buildJsonObject {
            put("wall_seconds", num(wall.inWholeMilliseconds / 1000.0))
            put("waypoints", o.waypoints)
            put("spacing_m", num(o.spacing))
            put("height_m", num(o.height))
            put("action_s", num(o.action.seconds()))
            putJsonArray("flights") {
                for (f in flights) addJsonObject {
                    put("autopilot", f.autopilot.name)
                    put("condition", f.condition.name)
                    put("mechanism", f.mechanism.name)
                    put("rep", f.rep)
                    f.error?.let { put("error", JsonPrimitive(it)) }
                    f.timings?.let { t ->
                        put("total_s", num(t.total))
                        putJsonArray("waypoints") {
                            for (w in t.waypoints) addJsonObject {
                                put("index", w.index)
                                put("arrived", num(w.arrived))
                                put("action_start", num(w.actionStart))
                                put("action_end", num(w.actionEnd))
                                put("moving", num(w.moving))
                                put("offset_m", num(w.offsetAtAction))
                            }
                        }
                    }
                }
            }
        },
    )

    private fun medMax(values: List<Double>): String = if (values.isEmpty()) "–" else "${fmt(percentile(values, 50.0))} / ${fmt(values.max())}"

    private fun fmt(v: Double?): String = when {
        v == null || !v.isFinite() -> "–"
        kotlin.math.abs(v) < 10 -> String.format(Locale.ROOT, "%.2f", v)
        else -> String.format(Locale.ROOT, "%.1f", v)
    }
}
