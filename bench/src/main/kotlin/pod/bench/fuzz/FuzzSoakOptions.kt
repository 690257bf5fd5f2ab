package pod.bench.fuzz

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
import java.io.File
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes

/** Command line of the decoder soak run; see [main]. */
data class FuzzSoakOptions(
    /** Mutated inputs per decoder. */
    val inputs: Long = 10_000_000,
    val seed: Long = 20261128,
    /** Decoders to run, by target name; empty: all of them. */
    val decoders: List<String> = emptyList(),
    /** Decoders run at once (each on a thread of its own). */
    val threads: Int = 2,
    /** An input running this long is a hang (generous: inputs take microseconds). */
    val stuckAfter: Duration = 1.minutes,
    val json: File? = null,
    val markdown: File? = null,
) {
    companion object {
        /** The options [args] give. */
        fun parse(args: Array<String>): FuzzSoakOptions = FuzzSoakCommand().parse(args)
    }
}

/** [FuzzSoakOptions] read from the command line. */
private class FuzzSoakCommand : BenchCommand<FuzzSoakOptions>("FuzzSoakKt", "Every decoder under millions of seeded mutated inputs: escapes, hangs and inputs/s.") {
    private val d = FuzzSoakOptions()
    private val inputs by option("--inputs", help = "mutated inputs per decoder").convert("COUNT") { text ->
        text.trim().replace("_", "").toLongOrNull()?.takeIf { it in 1..1_000_000_000L } ?: fail("must be a whole number in 1..1000000000, was $text")
    }.default(d.inputs)
    private val seed by option("--seed").long().default(d.seed)
    private val decoders by option("--decoders", help = "target names, comma-separated (datagram,stream,signed,tlog); all by default").split(",").default(d.decoders)
    private val threads by option("--threads", help = "decoders run at once").count(1..16).default(d.threads)
    private val stuckAfter by option("--stuck-after", help = "an input running this long is a hang").duration(100.milliseconds..1.hours).default(d.stuckAfter)
    private val report by ReportFiles()

    override fun options(): FuzzSoakOptions = FuzzSoakOptions(inputs, seed, decoders, threads, stuckAfter, report.json, report.markdown)
}
