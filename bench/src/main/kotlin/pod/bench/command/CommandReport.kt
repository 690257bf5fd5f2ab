package pod.bench.command

import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.add
import kotlinx.serialization.json.buildJsonObject
import kotlinx.serialization.json.put
import kotlinx.serialization.json.putJsonArray
import kotlinx.serialization.json.putJsonObject
import pod.bench.JsonText
import pod.bench.JsonText.num
import java.util.Locale
import kotlin.time.Duration

/** The command harness's results as a Markdown table and as JSON. */
object CommandReport {
    fun markdown(r: CommandResults, wall: Duration): String = buildString {
        val o = r.options
        appendLine("### Command round trip: Pod vs pymavlink as ground station, simulated vehicles on loopback, every vehicle commanded at once")
        appendLine()
        appendLine(
            "MAV_CMD_SET_MESSAGE_INTERVAL (SYS_STATUS, 1,000,000 µs) as COMMAND_LONG → COMMAND_ACK; fresh fleet per ground station and case " +
                "(vehicles in their own JVM, warmed up there: ${r.fleetReady}); rounds ${o.gap} apart; latency per command " +
                "from the caller's send to its return (Pod) or from the first send to the ack's arrival (pymavlink, resend after ${o.pythonResend}):",
        )
        appendLine()
        appendLine("| vehicles | loss each way | ground station | rounds | median ms | p90 ms | p99 ms | max ms | round makespan median ms | commands/s | resends | failed | CPU µs/command: station / fleet |")
        appendLine("|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for (run in r.runs) {
            val c = run.case
            if (run.setupError != null) {
                appendLine("| ${c.vehicles} | ${c.lossPercent} % | ${run.station.label} | ✗ | ${run.setupError} | | | | | | | | |")
                continue
            }
            appendLine(
                fmt(
                    "| %d | %d %% | %s | %d | %.3f | %.3f | %.3f | %.3f | %.3f | %,.0f | %d | %d of %d | %.0f / %.0f |",
                    c.vehicles, c.lossPercent, run.station.label, run.rounds.size, run.latencyMs(50.0), run.latencyMs(90.0),
                    run.latencyMs(99.0), run.maxMs, run.medianMakespanMs, run.commandsPerSecond, run.resends, run.failures, run.commands,
                    run.gcsCpuUsPerCommand, run.fleetCpuUsPerCommand,
                ),
            )
        }
        val splits = r.runs.filter { it.split != null }
        if (splits.isNotEmpty()) {
            appendLine()
            appendLine("Where Pod's time goes (medians over commands acknowledged at the first send; stamps at Pod's link):")
            appendLine()
            appendLine("| vehicles | loss each way | commands | caller → link ms | link send (Ktor) ms | link sent → ack out of link receive ms | ack out of link → caller returns ms |")
            appendLine("|---:|---:|---:|---:|---:|---:|---:|")
            for (run in splits) {
                val s = run.split!!
                appendLine(
                    fmt(
                        "| %d | %d %% | %d | %.3f | %.3f | %.3f | %.3f |", run.case.vehicles, run.case.lossPercent, s.samples,
                        s.toSocketUs / 1e3, s.socketSendUs / 1e3, s.wireUs / 1e3, s.toCallerUs / 1e3,
                    ),
                )
            }
        }
        val lossy = r.runs.filter { it.case.lossPercent > 0 && it.setupError == null }
        if (lossy.isNotEmpty()) {
            appendLine()
            for (run in lossy) {
                appendLine(
                    fmt(
                        "- %s, %s: mean latency %.1f ms, p75 %.1f ms; relays dropped %d datagrams to the ground station, %d to the vehicles",
                        run.station.label, run.case.label, run.latencies.average() / 1e3, run.latencyMs(75.0), run.droppedToGcs, run.droppedToVehicle,
                    ),
                )
            }
        }
        val failed = r.runs.filter { it.errors.isNotEmpty() }
        if (failed.isNotEmpty()) {
            appendLine()
            appendLine("Failed commands:")
            appendLine()
            for (run in failed) for ((error, n) in run.errors.groupingBy { it }.eachCount()) appendLine("- ${run.station.label}, ${run.case.label}: ${n}× `$error`")
        }
        appendLine()
        appendLine(fmt("Harness wall time %.1f min.", wall.inWholeMilliseconds / 60_000.0))
    }

    fun json(r: CommandResults, wall: Duration): String = JsonText.pretty.encodeToString(
        JsonObject.serializer(),
        buildJsonObject {
            val o = r.options
            put("wallSeconds", num(wall.inWholeMilliseconds / 1e3))
            putJsonObject("settings") {
                put("gapMs", o.gap.inWholeMilliseconds)
                put("pythonResendMs", o.pythonResend.inWholeMilliseconds)
                put("podWarmUpRounds", o.podWarmUpRounds)
                put("seed", o.seed)
                put("fleetReady", r.fleetReady)
            }
            putJsonArray("runs") { r.runs.forEach { add(runJson(it)) } }
        },
    ) + "\n"

    private fun runJson(run: CommandRun): JsonObject = buildJsonObject {
        val c = run.case
        val s = run.split
        put("station", run.station.name)
        put("vehicles", c.vehicles)
        put("lossPercent", c.lossPercent)
        put("rounds", run.rounds.size)
        put("warmUpRounds", c.warmUp)
        put("setupError", run.setupError)
        put("discoverySeconds", num(run.discoverySeconds))
        put("commands", run.commands)
        put("acknowledged", run.acknowledged)
        put("failures", run.failures)
        put("resends", run.resends)
        putJsonObject("latencyMs") {
            put("median", num(run.latencyMs(50.0)))
            put("p90", num(run.latencyMs(90.0)))
            put("p99", num(run.latencyMs(99.0)))
            put("max", num(run.maxMs))
        }
        put("makespanMedianMs", num(run.medianMakespanMs))
        put("commandsPerSecond", num(run.commandsPerSecond))
        putJsonArray("makespansMs") { run.rounds.forEach { add(num(it.makespanUs / 1e3)) } }
        putJsonArray("latenciesMs") { run.latencies.forEach { add(num(it / 1e3)) } }
        if (s == null) {
            put("podSplitMs", JsonNull)
        } else {
            putJsonObject("podSplitMs") {
                put("samples", s.samples)
                put("callerToLink", num(s.toSocketUs / 1e3))
                put("linkSend", num(s.socketSendUs / 1e3))
                put("wire", num(s.wireUs / 1e3))
                put("ackToCaller", num(s.toCallerUs / 1e3))
            }
        }
        put("gcsCpuSeconds", num(run.gcsCpuSeconds))
        put("fleetCpuSeconds", num(run.fleetCpuSeconds))
        putJsonArray("errors") { run.errors.forEach { add(it) } }
        put("droppedToGcs", run.droppedToGcs)
        put("droppedToVehicle", run.droppedToVehicle)
    }

    fun describe(run: CommandRun): String =
        if (run.setupError != null) {
            fmt("%-9s %-28s SETUP FAILED: %s", run.station.label, run.case.label, run.setupError)
        } else {
            fmt(
                "%-9s %-28s median %.3f  p90 %.3f  p99 %.3f  max %.3f ms  makespan %.3f ms  %,.0f cmd/s  resends %d  failed %d/%d  CPU µs/cmd %.0f / %.0f",
                run.station.label, run.case.label, run.latencyMs(50.0), run.latencyMs(90.0), run.latencyMs(99.0), run.maxMs,
                run.medianMakespanMs, run.commandsPerSecond, run.resends, run.failures, run.commands, run.gcsCpuUsPerCommand, run.fleetCpuUsPerCommand,
            ) + (run.split?.let { fmt("  [split: %.3f / %.3f / %.3f / %.3f ms]", it.toSocketUs / 1e3, it.socketSendUs / 1e3, it.wireUs / 1e3, it.toCallerUs / 1e3) } ?: "") +
                run.errors.take(3).joinToString("") { "\n      failed: $it" }
        }

    private fun fmt(format: String, vararg args: Any?): String = String.format(Locale.ROOT, format, *args)
}
