package pod.bench.command

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
        fun parse(args: Array<String>): CommandBenchOptions {
            var o = CommandBenchOptions()
            var i = 0
            fun ints(value: String) = value.split(',').map { it.trim().toInt() }
            while (i < args.size) {
                val value = args.getOrNull(i + 1) ?: error("missing value after ${args[i]}")
                o = when (args[i]) {
                    "--counts" -> o.copy(counts = ints(value).onEach { require(it in 1..250) { "counts must be in 1..250, was $it" } })
                    "--rounds" -> o.copy(rounds = ints(value).onEach { require(it in 1..10_000) { "rounds must be in 1..10000, was $it" } })
                    "--warmup" -> o.copy(warmUps = ints(value).onEach { require(it in 0..10_000) { "warmup must be in 0..10000, was $it" } })
                    "--lossy-count" -> o.copy(lossyCount = value.toInt().also { require(it in 0..250) { "lossy-count must be in 0..250, was $it" } })
                    "--lossy-rounds" -> o.copy(lossyRounds = value.toInt().also { require(it in 1..10_000) { "lossy-rounds must be in 1..10000, was $it" } })
                    "--lossy-warmup" -> o.copy(lossyWarmUp = value.toInt().also { require(it in 0..10_000) { "lossy-warmup must be in 0..10000, was $it" } })
                    "--loss" -> o.copy(lossPercent = value.toInt().also { require(it in 1..90) { "loss must be a percentage in 1..90, was $it" } })
                    "--stations" -> o.copy(stations = value.split(',').map { CommandStation.valueOf(it.trim().uppercase()) })
                    "--gap" -> o.copy(gap = Duration.parse(value).also { require(it in Duration.ZERO..10.seconds) { "gap must be in 0s..10s, was $it" } })
                    "--pod-warmup" -> o.copy(podWarmUpRounds = value.toInt().also { require(it in 0..100_000) { "pod-warmup must be in 0..100000, was $it" } })
                    "--python-resend" -> o.copy(pythonResend = Duration.parse(value).also { require(it in 10.milliseconds..10.seconds) })
                    "--seed" -> o.copy(seed = value.toLong())
                    "--python" -> o.copy(python = File(value))
                    "--script" -> o.copy(script = File(value))
                    "--peer-log" -> o.copy(peerLog = File(value))
                    "--json" -> o.copy(json = File(value))
                    "--markdown" -> o.copy(markdown = File(value))
                    else -> error("unknown option ${args[i]}")
                }
                i += 2
            }
            require(o.rounds.size == o.counts.size && o.warmUps.size == o.counts.size) {
                "counts, rounds and warmup must have as many entries each, were ${o.counts}, ${o.rounds}, ${o.warmUps}"
            }
            return o
        }
    }
}
