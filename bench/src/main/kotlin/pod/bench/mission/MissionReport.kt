package pod.bench.mission

import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.add
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

/** The harness's results as Markdown tables and as JSON. */
object MissionReport {
    fun markdown(r: MissionResults, wall: Duration): String = buildString {
        appendLine("### Mission transfer: Pod vs MAVSDK 4.1 (MissionRaw) as ground station, simulated vehicle, seeded lossy UDP relay on loopback")
        appendLine()
        appendLine("Floor (ping-pong of one HEARTBEAT frame, one in flight; every transfer crosses the same relay):")
        appendLine()
        appendLine("| path | round trips | median ms | p99 ms | lost |")
        appendLine("|---|---:|---:|---:|---:|")
        for (f in r.floor) appendLine(fmt("| %s | %d | %.3f | %.3f | %d |", f.path, f.samples.size, f.medianMs, f.p99Ms, f.lost))
        appendLine()
        appendLine("Transfers (one seeded run per cell, same seed for both ground stations; seconds; ✗ = failed after that long, reason below):")
        appendLine()
        appendLine("| vehicle | items | loss each way | Pod upload s | MAVSDK upload s | Pod download s | MAVSDK download s |")
        appendLine("|---|---:|---:|---:|---:|---:|---:|")
        for ((cell, runs) in r.grid.groupBy { it.cell }) {
            val pod = runs.firstOrNull { it.station == Station.POD }
            val mav = runs.firstOrNull { it.station == Station.MAVSDK }
            appendLine(
                "| ${cell.flavour.name} | ${cell.items} | ${cell.lossPercent} % | ${upload(pod)} | ${upload(mav)} | ${download(pod)} | ${download(mav)} |",
            )
        }
        appendLine()
        val o = r.options
        appendLine(
            "Success rate (${o.successRuns} seeded runs each, ${o.successItems} items, ${o.successLossPercent} % loss each way; times of the successful runs; " +
                "Pod's timeouts ${o.timing.minTimeout} minimum, ${o.timing.initialTimeout} initial):",
        )
        appendLine()
        appendLine("| vehicle | ground station | upload ok | upload + download verified | upload s median / p90 | upload + download s median / p90 |")
        appendLine("|---|---|---:|---:|---:|---:|")
        for ((key, runs) in r.success.groupBy { it.cell.flavour to it.station }) {
            val uploads = runs.filter { it.uploaded }.map { it.upload!!.seconds }
            val totals = runs.mapNotNull { it.totalSeconds }
            appendLine(
                "| ${key.first.name} | ${key.second.label} | ${runs.count { it.uploaded }}/${runs.size} | ${totals.size}/${runs.size} | " +
                    "${medianP90(uploads)} | ${medianP90(totals)} |",
            )
        }
        val failures = (r.grid + r.success).filter { !it.verified }
        if (failures.isNotEmpty()) {
            appendLine()
            appendLine("Failures (${failures.size}):")
            appendLine()
            for (f in failures) appendLine("- ${f.station.label}, ${f.cell.label}, seed ${f.seed}: ${reason(f)}")
        }
        appendLine()
        appendLine(fmt("Harness wall time %.1f min.", wall.inWholeMilliseconds / 60_000.0))
    }

    private fun upload(run: TransferRun?): String = when {
        run == null -> "–"
        run.upload == null -> "✗ setup"
        else -> cell(run.upload)
    }

    private fun download(run: TransferRun?): String = when {
        run?.download == null -> "–"
        run.mismatch != null -> "✗ mismatch"
        else -> cell(run.download)
    }

    private fun cell(step: Step): String = if (step.ok) fmt("%.3f", step.seconds) else fmt("✗ %.1f (%s)", step.seconds, step.errorKind)

    private fun medianP90(values: List<Double>): String =
        if (values.isEmpty()) "–" else fmt("%.2f / %.2f", percentile(values, 50.0), percentile(values, 90.0))

    private fun reason(run: TransferRun): String = run.setupError
        ?: run.upload?.takeIf { !it.ok }?.let { fmt("upload failed after %.1f s: `%s`", it.seconds, it.error) }
        ?: run.download?.takeIf { !it.ok }?.let { fmt("download failed after %.1f s: `%s`", it.seconds, it.error) }
        ?: run.mismatch?.let { "download differs: $it" }
        ?: "?"

    fun json(r: MissionResults, wall: Duration): String = JsonText.pretty.encodeToString(
        JsonObject.serializer(),
        buildJsonObject {
            val o = r.options
            put("wallSeconds", num(wall.inWholeMilliseconds / 1e3))
            putJsonObject("settings") {
                putJsonArray("sizes") { o.sizes.forEach { add(it) } }
                putJsonArray("lossPercents") { o.lossPercents.forEach { add(it) } }
                putJsonArray("flavours") { o.flavours.forEach { add(it.name) } }
                put("successRuns", o.successRuns)
                put("successItems", o.successItems)
                put("successLossPercent", o.successLossPercent)
                put("discoveryLimitSeconds", o.limits.discovery.inWholeSeconds)
                put("transferLimitSeconds", o.limits.transfer.inWholeSeconds)
                put("seed", o.seed)
                put("podMinTimeoutMs", o.timing.minTimeout.inWholeMilliseconds)
                put("podInitialTimeoutMs", o.timing.initialTimeout.inWholeMilliseconds)
            }
            putJsonArray("floor") {
                for (f in r.floor) {
                    addJsonObject {
                        put("path", f.path)
                        put("samples", f.samples.size)
                        put("lost", f.lost)
                        put("medianMs", num(f.medianMs))
                        put("p99Ms", num(f.p99Ms))
                    }
                }
            }
            putJsonArray("grid") { r.grid.forEach { add(runJson(it)) } }
            putJsonArray("successRate") { r.success.forEach { add(runJson(it)) } }
        },
    ) + "\n"

    private fun runJson(t: TransferRun): JsonObject = buildJsonObject {
        put("station", t.station.name)
        put("flavour", t.cell.flavour.name)
        put("items", t.cell.items)
        put("lossPercent", t.cell.lossPercent)
        put("seed", t.seed)
        put("upload", stepJson(t.upload))
        put("download", stepJson(t.download))
        put("verified", t.verified)
        put("mismatch", t.mismatch)
        put("setupError", t.setupError)
        put("droppedToGcs", t.droppedToGcs)
        put("droppedToVehicle", t.droppedToVehicle)
    }

    private fun stepJson(s: Step?): JsonElement =
        if (s == null) JsonNull else buildJsonObject { put("ok", s.ok); put("seconds", num(s.seconds)); put("error", s.error) }

    private fun fmt(format: String, vararg args: Any?): String = String.format(Locale.ROOT, format, *args)
}
