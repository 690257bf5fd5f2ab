package pod.bench.tlog

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
    /** Replay speeds; 1e9 plays faster than the link can deliver, so the pacing never waits. */
    val speeds: List<Double> = listOf(1000.0, 1e9),
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
        fun parse(args: Array<String>): TlogBenchOptions {
            var o = TlogBenchOptions()
            var i = 0
            while (i < args.size) {
                val value = args.getOrNull(i + 1) ?: error("missing value after ${args[i]}")
                fun count(range: IntRange) = value.toInt().also { require(it in range) { "${args[i]} must be in $range, was $it" } }
                o = when (args[i]) {
                    "--vehicles" -> o.copy(vehicles = count(1..250))
                    "--duration" -> o.copy(duration = Duration.parse(value).also { require(it in 1.seconds..24.hours) { "duration must be in 1s..24h, was $it" } })
                    "--seed" -> o.copy(seed = value.toLong())
                    "--log" -> o.copy(log = File(value))
                    "--reads" -> o.copy(reads = count(1..100))
                    "--warmup" -> o.copy(warmUp = count(0..100))
                    "--python-reads" -> o.copy(pythonReads = count(0..100))
                    "--python-warmup" -> o.copy(pythonWarmUp = count(0..100))
                    "--speeds" -> o.copy(speeds = value.split(',').map { s -> s.trim().toDouble().also { require(it > 0 && it.isFinite()) { "speeds must be finite and > 0, was $it" } } })
                    "--replays" -> o.copy(replays = count(1..100))
                    "--replay-warmup" -> o.copy(replayWarmUp = count(0..100))
                    "--bare-replay" -> o.copy(bareReplay = value.toBooleanStrict())
                    "--python" -> o.copy(python = File(value))
                    "--script" -> o.copy(script = File(value))
                    "--peer-log" -> o.copy(peerLog = File(value))
                    "--json" -> o.copy(json = File(value))
                    "--markdown" -> o.copy(markdown = File(value))
                    else -> error("unknown option ${args[i]}")
                }
                i += 2
            }
            return o
        }
    }
}
