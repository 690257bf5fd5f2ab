package pod.bench.command

import com.github.ajalt.clikt.core.UsageError
import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.long
import pod.bench.BenchCommand
import pod.bench.ReportFiles
import pod.bench.count
import pod.bench.counts
import pod.bench.duration
import pod.bench.file
import pod.bench.names
import java.io.File
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** Command line of the command round-trip harness; see [main]. */
data class CommandBenchOptions(
    val counts: List<Int> = listOf(1, 10, 100),
    val rounds: List<Int> = listOf(200, 50, 20),
    val warmUps: List<Int> = listOf(20, 5, 3),
    /** The lossy case: vehicles, rounds, warm-up rounds, loss each way (vehicles 0: no lossy case). */
    val lossyCount: Int = 10,
    val lossyRounds: Int = 30,
    val lossyWarmUp: Int = 3,
    val lossPercent: Int = 30,
    val stations: List<CommandStation> = CommandStation.entries,
    /** Idle time between rounds, for both stations: stragglers drain, and commanding is not back to back in practice. */
    val gap: Duration = 20.milliseconds,
    /** Rounds of the discarded warm-up case Pod runs first (10 vehicles), so that its JIT has seen the path. */
    val podWarmUpRounds: Int = 200,
    /** pymavlink's resend timeout. */
    val pythonResend: Duration = 500.milliseconds,
    val discovery: Duration = 30.seconds,
    val seed: Long = 1,
    val python: File = File(".venv/bin/python"),
    val script: File = File("bench/pymavlink_command.py"),
    val peerLog: File? = null,
    val json: File? = null,
    val markdown: File? = null,
) {
    val cases: List<CommandCase>
        get() = counts.indices.map { CommandCase(counts[it], rounds[it], warmUps[it]) } +
            if (lossyCount > 0) listOf(CommandCase(lossyCount, lossyRounds, lossyWarmUp, lossPercent)) else emptyList()

    companion object {
        /** The options [args] give (see [main] for the list). */
        fun parse(args: Array<String>): CommandBenchOptions = CommandBenchCommand().parse(args)
    }
}

/** [CommandBenchOptions] read from the command line. */
private class CommandBenchCommand : BenchCommand<CommandBenchOptions>("CommandBenchKt", "The command round trip on loopback, Pod against pymavlink.") {
    private val d = CommandBenchOptions()
    private val counts by option("--counts", help = "vehicles per case").counts(1..250).default(d.counts)
    private val rounds by option("--rounds", help = "measured rounds per case").counts(1..10_000).default(d.rounds)
    private val warmUps by option("--warmup", help = "warm-up rounds per case").counts(0..10_000).default(d.warmUps)
    private val lossyCount by option("--lossy-count", help = "vehicles of the lossy case (0: none)").count(0..250).default(d.lossyCount)
    private val lossyRounds by option("--lossy-rounds").count(1..10_000).default(d.lossyRounds)
    private val lossyWarmUp by option("--lossy-warmup").count(0..10_000).default(d.lossyWarmUp)
    private val lossPercent by option("--loss", help = "loss each way in the lossy case, %").count(1..90).default(d.lossPercent)
    private val stations by option("--stations").names<CommandStation>().default(d.stations)
    private val gap by option("--gap", help = "idle time between rounds").duration(Duration.ZERO..10.seconds).default(d.gap)
    private val podWarmUpRounds by option("--pod-warmup").count(0..100_000).default(d.podWarmUpRounds)
    private val pythonResend by option("--python-resend").duration(10.milliseconds..10.seconds).default(d.pythonResend)
    private val seed by option("--seed").long().default(d.seed)
    private val python by option("--python").file().default(d.python)
    private val script by option("--script").file().default(d.script)
    private val peerLog by option("--peer-log").file()
    private val report by ReportFiles()

    override fun options(): CommandBenchOptions {
        if (rounds.size != counts.size || warmUps.size != counts.size) {
            throw UsageError("counts, rounds and warmup must have as many entries each, were $counts, $rounds, $warmUps")
        }
        return CommandBenchOptions(
            counts, rounds, warmUps, lossyCount, lossyRounds, lossyWarmUp, lossPercent, stations, gap, podWarmUpRounds,
            pythonResend, d.discovery, seed, python, script, peerLog, report.json, report.markdown,
        )
    }
}
