package pod.bench.tlog

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.int
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import pod.bench.PeerProcess
import java.nio.file.Path
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * bench/pymavlink_tlog.py reading the log [TlogBenchOptions.pythonWarmUp] + [TlogBenchOptions.pythonReads]
 * times in one Python process; the measured passes, each checked as Pod's reads are (every record,
 * no BAD_DATA, every vehicle's GLOBAL_POSITION_INT count and last position). Times are the script's
 * own (perf_counter, process_time), so Python's start-up is not counted. Second: why the script
 * did not run to the end, or null.
 */
fun pymavlinkReads(path: Path, expected: LogContents, o: TlogBenchOptions): Pair<List<Pass>, String?> {
    val passes = ArrayList<Pass>()
    val peer = PeerProcess(
        listOf(o.python.path, o.script.path, path.toString(), "--runs", o.pythonReads.toString(), "--warmup", o.pythonWarmUp.toString()),
        "pymavlink tlog read", o.peerLog,
    )
    peer.use {
        repeat(o.pythonWarmUp + o.pythonReads) {
            // A read of a 14 MB log takes pymavlink about ten seconds here; a tenfold margin.
            val run = peer.await("run", 2.minutes)
            if (run?.get("event") != "run") return passes to "pymavlink read did not finish: ${run ?: "nothing within 2 min"}; ${peer.stderrLines().takeLast(5)}"
            if (run["warmup"] == "true") return@repeat
            passes += run.toPass(expected)
        }
        peer.await("done", 10.seconds)
    }
    return passes to null
}

private fun Map<String, String>.toPass(expected: LogContents): Pass {
    val records = getValue("records").toLong()
    val positions = Json.parseToJsonElement(getValue("positions")).jsonObject.mapKeys { it.key.toInt() }.mapValues { it.value.jsonPrimitive.int }
    val last = Json.parseToJsonElement(getValue("last")).jsonObject.mapKeys { it.key.toInt() }
        .mapValues { (_, v) -> v.jsonArray.map { it.jsonPrimitive.int }.let { (lat, lon, alt) -> LoggedPosition(lat, lon, alt) } }
    val problems = buildList {
        if (records != expected.records) add("read $records records, the log has ${expected.records}")
        getValue("bad").toLong().takeIf { it > 0 }?.let { add("$it BAD_DATA") }
        if (positions != expected.positions) add("positions per vehicle $positions, the log has ${expected.positions}")
        if (last != expected.last) add("last positions $last, the log has ${expected.last}")
    }
    return Pass(getValue("seconds").toDouble(), get("cpu_seconds")?.toDoubleOrNull(), records, problems)
}
