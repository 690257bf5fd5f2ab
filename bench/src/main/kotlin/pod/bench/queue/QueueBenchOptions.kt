package pod.bench.queue

import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.long
import pod.bench.BenchCommand
import pod.bench.ReportFiles
import pod.bench.count
import pod.bench.counts
import pod.bench.duration
import pod.bench.names
import pod.sim.fault.LinkFaults
import java.io.File
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/** A link between station and vehicle: straight sockets on loopback, or through a relay with [faults] each way. */
enum class LinkCondition(val label: String, val faults: LinkFaults?) {
    LOOPBACK("loopback", null),
    RTT100("100 ms RTT", LinkFaults(delay = 50.milliseconds)),
    RTT100_LOSS20("100 ms RTT, 20 % loss each way", LinkFaults(delay = 50.milliseconds, drop = 0.2)),
}

/** How a change in flight reaches the vehicle. */
enum class ChangeMethod(val label: String) {
    QUEUE("queue: replaceCurrent (one DO_REPOSITION)"),
    REUPLOAD("re-upload: whole mission + MISSION_SET_CURRENT"),
}

/** Command line of the queue benchmark; see [main]. */
data class QueueBenchOptions(
    val sizes: List<Int> = listOf(10, 100),
    val conditions: List<LinkCondition> = listOf(LinkCondition.LOOPBACK, LinkCondition.RTT100),
    val methods: List<ChangeMethod> = ChangeMethod.entries,
    val reps: Int = 30,
    val warmUp: Int = 5,
    /** Repetitions under loss (each re-upload then takes seconds). */
    val lossyReps: Int = 10,
    /** Pause between two changes, so that the last one's acknowledgement is home before the next starts. */
    val gap: Duration = 300.milliseconds,
    /** Longest one change may take to show at the vehicle; longer counts as failed. */
    val limit: Duration = 60.seconds,
    val seed: Long = 1,
    val json: File? = null,
    val markdown: File? = null,
) {
    /** Measured repetitions for [condition]. */
    fun repsFor(condition: LinkCondition): Int = if (condition.faults?.drop?.let { it > 0 } == true) lossyReps else reps

    companion object {
        /** The options [args] give (see [main] for the list). */
        fun parse(args: Array<String>): QueueBenchOptions = QueueBenchCommand().parse(args)
    }
}

/** [QueueBenchOptions] read from the command line. */
private class QueueBenchCommand : BenchCommand<QueueBenchOptions>("QueueBenchKt", "A change in flight through the queue against a re-upload.") {
    private val d = QueueBenchOptions()
    private val sizes by option("--sizes", help = "mission sizes").counts(1..1000).default(d.sizes)
    private val conditions by option("--conditions").names<LinkCondition>().default(d.conditions)
    private val methods by option("--methods").names<ChangeMethod>().default(d.methods)
    private val reps by option("--reps").count(1..1000).default(d.reps)
    private val warmUp by option("--warmup").count(0..1000).default(d.warmUp)
    private val lossyReps by option("--lossy-reps").count(1..1000).default(d.lossyReps)
    private val gap by option("--gap").duration(Duration.ZERO..10.seconds).default(d.gap)
    private val limit by option("--limit").duration(1.seconds..10.minutes).default(d.limit)
    private val seed by option("--seed").long().default(d.seed)
    private val report by ReportFiles()

    override fun options(): QueueBenchOptions =
        QueueBenchOptions(sizes, conditions, methods, reps, warmUp, lossyReps, gap, limit, seed, report.json, report.markdown)
}
