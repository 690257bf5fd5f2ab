package pod.bench.tlog

import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.options.split
import com.github.ajalt.clikt.parameters.types.long
import pod.bench.BenchCommand
import pod.bench.ReportFiles
import pod.bench.count
import pod.bench.duration
import pod.bench.file
import pod.bench.yesNo
import java.io.File
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.seconds

/** Command line of the tlog benchmark; see [main]. */
data class TlogBenchOptions(
    val vehicles: Int = 4,
    val duration: Duration = 1.hours,
    val seed: Long = 1,
    /** Where the synthetic log is written. */
    val log: File = File("bench/target/tlog/synthetic.tlog"),
    /** Measured Pod reads, after [warmUp] not kept. */
    val reads: Int = 5,
    val warmUp: Int = 2,
    /** Measured pymavlink reads, after [pythonWarmUp] not kept (one process for all). */
    val pythonReads: Int = 5,
    val pythonWarmUp: Int = 1,
    /** Replay speeds; infinite (`max`) plays unpaced, as fast as the station takes the log. */
    val speeds: List<Double> = listOf(1000.0, Double.POSITIVE_INFINITY),
    /** Measured replays per speed, after [replayWarmUp] not kept. */
    val replays: Int = 3,
    val replayWarmUp: Int = 1,
    /** Whether to add a replay without a TrackRecorder tap at the highest speed. */
    val bareReplay: Boolean = true,
    val python: File = File(".venv/bin/python"),
    val script: File = File("bench/pymavlink_tlog.py"),
    val peerLog: File? = null,
    val json: File? = null,
    val markdown: File? = null,
) {
    companion object {
        /** The options [args] give (see [main] for the list). */
        fun parse(args: Array<String>): TlogBenchOptions = TlogBenchCommand().parse(args)
    }
}

/** [TlogBenchOptions] read from the command line. */
private class TlogBenchCommand : BenchCommand<TlogBenchOptions>("TlogBenchKt", "Reading and replaying a synthetic tlog, Pod against pymavlink.") {
    private val d = TlogBenchOptions()
    private val vehicles by option("--vehicles").count(1..250).default(d.vehicles)
    private val duration by option("--duration", help = "length of the synthetic log").duration(1.seconds..24.hours).default(d.duration)
    private val seed by option("--seed").long().default(d.seed)
    private val log by option("--log", help = "where the synthetic log is written").file().default(d.log)
    private val reads by option("--reads").count(1..100).default(d.reads)
    private val warmUp by option("--warmup").count(0..100).default(d.warmUp)
    private val pythonReads by option("--python-reads").count(0..100).default(d.pythonReads)
    private val pythonWarmUp by option("--python-warmup").count(0..100).default(d.pythonWarmUp)
    private val speeds by option("--speeds", help = "replay speeds (max: unpaced, as `pod replay --speed max`)").convert("SPEED") { text ->
        if (text.trim() == "max") Double.POSITIVE_INFINITY else text.trim().toDoubleOrNull()?.takeIf { it > 0 } ?: fail("must be a number > 0 or max, was $text")
    }.split(",").default(d.speeds)
    private val replays by option("--replays").count(1..100).default(d.replays)
    private val replayWarmUp by option("--replay-warmup").count(0..100).default(d.replayWarmUp)
    private val bareReplay by option("--bare-replay").yesNo().default(d.bareReplay)
    private val python by option("--python").file().default(d.python)
    private val script by option("--script").file().default(d.script)
    private val peerLog by option("--peer-log").file()
    private val report by ReportFiles()

    override fun options(): TlogBenchOptions = TlogBenchOptions(
        vehicles, duration, seed, log, reads, warmUp, pythonReads, pythonWarmUp, speeds, replays, replayWarmUp, bareReplay,
        python, script, peerLog, report.json, report.markdown,
    )
}
