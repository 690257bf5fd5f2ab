package pod.bench.tlog

import kotlinx.coroutines.runBlocking
import java.util.Locale
import kotlin.system.exitProcess
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * Issue 16's benchmark: Pod reading and replaying a tlog, beside pymavlink reading the same file.
 *
 * Writes a seeded synthetic log ([SyntheticTlog]: copters streaming as ArduCopter does, a ground
 * station's heartbeat) with Pod's TlogWriter, then, in this order, on the same file:
 * 1. Pod's `TlogTracks.read` (every vehicle's track: every record read, HEARTBEAT, GLOBAL_POSITION_INT
 *    and HOME_POSITION decoded), and `TlogReader.next()` alone (framing and checksums, nothing decoded);
 * 2. pymavlink (bench/pymavlink_tlog.py: `mavutil.mavlink_connection` + `recv_msg()` to the end,
 *    GLOBAL_POSITION_INT per vehicle kept as its track);
 * 3. the log replayed through a `TlogReplayLink` to a `GroundStation`, wired as `pod replay` wires
 *    it, at each of [TlogBenchOptions.speeds] with a TrackRecorder tap, and at the highest without.
 * Every pass is checked against what the generator wrote (records, positions per vehicle, the last
 * position of each); a pass that read something else is marked ✗ and the program exits with 1.
 *
 * Usage: `TlogBenchKt [--vehicles 4] [--duration 1h] [--seed 1] [--log FILE] [--reads 5] [--warmup 2]
 * [--python-reads 5] [--python-warmup 1] [--speeds 1000,max] [--replays 3] [--replay-warmup 1]
 * [--bare-replay true] [--python .venv/bin/python] [--script bench/pymavlink_tlog.py]
 * [--peer-log FILE] [--json FILE] [--markdown FILE]`. Every pass is bounded (a read by the file, the
 * Python peer by 2 minutes a read, a replay by its log time over its speed plus 2 minutes).
 */
fun main(args: Array<String>) {
    val o = TlogBenchOptions.parse(args)
    val started = TimeSource.Monotonic.markNow()
    o.log.absoluteFile.parentFile.mkdirs()
    val path = o.log.toPath()
    println("== writing the log: ${o.log}")
    val log = SyntheticTlog.write(path, o.vehicles, o.duration, o.seed)
    println("  " + TlogReport.describe(log, o))

    val cases = mutableListOf<TlogCase>()
    fun podCase(key: String, label: String, pass: () -> Pass) {
        repeat(o.warmUp) { pass() }
        val passes = List(o.reads) { pass() }
        cases += TlogCase(key, label, o.warmUp, passes).also { println("  " + line(it)) }
    }
    println("== Pod reads")
    podCase("pod-read", "Pod `TlogTracks.read`") { PodTlogRuns.readTracks(path, log) }
    podCase("pod-records", "Pod `TlogReader.next()` alone (no decode)") { PodTlogRuns.readRecords(path, log) }

    if (o.pythonReads > 0) {
        println("== pymavlink reads")
        val (passes, failure) = pymavlinkReads(path, log, o)
        cases += TlogCase("pymavlink-read", "pymavlink `recv_msg()` loop", o.pythonWarmUp, passes, failure).also { println("  " + line(it)) }
    }

    println("== Pod replays")
    runBlocking {
        val replays = o.speeds.map { it to true } + (if (o.bareReplay) listOf(o.speeds.max() to false) else emptyList())
        for ((speed, withTracks) in replays) {
            val limit = (log.logSeconds / speed).seconds + 2.minutes
            repeat(o.replayWarmUp) { PodTlogRuns.replay(path, speed, withTracks, log, limit) }
            val passes = List(o.replays) { PodTlogRuns.replay(path, speed, withTracks, log, limit) }
            val label = "Pod replay to a `GroundStation`, ${speedText(speed)}" + if (withTracks) " + `TrackRecorder`" else ", no tap"
            cases += TlogCase("replay-$speed-$withTracks", label, o.replayWarmUp, passes).also { println("  " + line(it)) }
        }
    }

    val wall = started.elapsedNow()
    println("== done in $wall")
    val markdown = TlogReport.markdown(log, cases, o)
    println()
    println(markdown)
    o.json?.let { it.parentFile?.mkdirs(); it.writeText(TlogReport.json(log, cases, o, wall)); println("wrote ${it.path}") }
    o.markdown?.let { it.parentFile?.mkdirs(); it.writeText(markdown); println("wrote ${it.path}") }
    if (cases.any { it.problems.isNotEmpty() }) {
        System.err.println("some passes did not read what the log holds: see the table")
        exitProcess(1)
    }
}

/** "1000×", or for a speed at which the pacing never waits "unpaced (speed 1e9)", or "unpaced (`--speed max`)". */
private fun speedText(speed: Double): String {
    if (speed.isInfinite()) return "unpaced (`--speed max`)"
    val exponent = kotlin.math.log10(speed)
    val text = if (exponent >= 4 && exponent == kotlin.math.floor(exponent)) "1e${exponent.toInt()}" else String.format(Locale.ROOT, "%.0f", speed)
    return if (speed >= 1e6) "unpaced (speed $text)" else "$text×"
}

private fun line(c: TlogCase): String {
    val status = c.problems.takeIf { it.isNotEmpty() }?.joinToString("; ", prefix = ", ✗ ") ?: ""
    val notes = c.notes.takeIf { it.isNotEmpty() }?.joinToString("; ", prefix = " (", postfix = ")") ?: ""
    return "${c.label}: median ${TlogReport.fmt(c.wall)} s, " +
        String.format(Locale.ROOT, "%.0f", c.recordsPerSecond) + " records/s, CPU ${TlogReport.fmt(c.cpu)} s$status$notes"
}
