package pod.bench.queue

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
        fun parse(args: Array<String>): QueueBenchOptions {
            var o = QueueBenchOptions()
            var i = 0
            while (i < args.size) {
                val value = args.getOrNull(i + 1) ?: error("missing value after ${args[i]}")
                fun count(range: IntRange) = value.toInt().also { require(it in range) { "${args[i]} must be in $range, was $it" } }
                o = when (args[i]) {
                    "--sizes" -> o.copy(sizes = value.split(',').map { it.trim().toInt().also { n -> require(n in 1..1000) { "sizes must be in 1..1000, was $n" } } })
                    "--conditions" -> o.copy(conditions = value.split(',').map { LinkCondition.valueOf(it.trim().uppercase().replace('-', '_')) })
                    "--methods" -> o.copy(methods = value.split(',').map { ChangeMethod.valueOf(it.trim().uppercase()) })
                    "--reps" -> o.copy(reps = count(1..1000))
                    "--warmup" -> o.copy(warmUp = count(0..1000))
                    "--lossy-reps" -> o.copy(lossyReps = count(1..1000))
                    "--gap" -> o.copy(gap = Duration.parse(value).also { require(it in Duration.ZERO..10.seconds) { "gap must be in 0..10s, was $it" } })
                    "--limit" -> o.copy(limit = Duration.parse(value).also { require(it in 1.seconds..10.minutes) { "limit must be in 1s..10m, was $it" } })
                    "--seed" -> o.copy(seed = value.toLong())
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
