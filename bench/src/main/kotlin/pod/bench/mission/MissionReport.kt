package pod.bench.mission

import pod.bench.JsonText.num
import pod.bench.JsonText.str
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

    fun json(r: MissionResults, wall: Duration): String = buildString {
        val o = r.options
        append("{\n  \"wallSeconds\": ${num(wall.inWholeMilliseconds / 1e3)},\n")
        append(
            "  \"settings\": {\"sizes\": ${o.sizes}, \"lossPercents\": ${o.lossPercents}, \"flavours\": ${o.flavours.map { str(it.name) }}, " +
                "\"successRuns\": ${o.successRuns}, \"successItems\": ${o.successItems}, \"successLossPercent\": ${o.successLossPercent}, " +
                "\"discoveryLimitSeconds\": ${o.limits.discovery.inWholeSeconds}, \"transferLimitSeconds\": ${o.limits.transfer.inWholeSeconds}, \"seed\": ${o.seed}, " +
                "\"podMinTimeoutMs\": ${o.timing.minTimeout.inWholeMilliseconds}, \"podInitialTimeoutMs\": ${o.timing.initialTimeout.inWholeMilliseconds}},\n",
        )
        append("  \"floor\": [\n")
        append(
            r.floor.joinToString(",\n") {
                "    {\"path\": ${str(it.path)}, \"samples\": ${it.samples.size}, \"lost\": ${it.lost}, " +
                    "\"medianMs\": ${num(it.medianMs)}, \"p99Ms\": ${num(it.p99Ms)}}"
            },
        )
        append("\n  ],\n  \"grid\": [\n")
        append(r.grid.joinToString(",\n") { "    " + runJson(it) })
        append("\n  ],\n  \"successRate\": [\n")
        append(r.success.joinToString(",\n") { "    " + runJson(it) })
        append("\n  ]\n}\n")
    }

    private fun runJson(t: TransferRun): String =
        "{\"station\": ${str(t.station.name)}, \"flavour\": ${str(t.cell.flavour.name)}, \"items\": ${t.cell.items}, " +
            "\"lossPercent\": ${t.cell.lossPercent}, \"seed\": ${t.seed}, \"upload\": ${stepJson(t.upload)}, " +
            "\"download\": ${stepJson(t.download)}, \"verified\": ${t.verified}, \"mismatch\": ${t.mismatch?.let(::str) ?: "null"}, " +
            "\"setupError\": ${t.setupError?.let(::str) ?: "null"}, \"droppedToGcs\": ${t.droppedToGcs}, \"droppedToVehicle\": ${t.droppedToVehicle}}"

    private fun stepJson(s: Step?): String =
        if (s == null) "null" else "{\"ok\": ${s.ok}, \"seconds\": ${num(s.seconds)}, \"error\": ${s.error?.let(::str) ?: "null"}}"

    private fun fmt(format: String, vararg args: Any?): String = String.format(Locale.ROOT, format, *args)
}
