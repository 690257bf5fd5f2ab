package pod.mavlink.fuzz

import kotlin.time.Duration
import kotlin.time.DurationUnit

/** What one [FuzzRun] saw. Clean ([clean]) means every input ran, none escaped, broke a property or hung. */
public data class FuzzReport(
    val target: String,
    val seed: Long,
    val requested: Long,
    val completed: Long,
    val escapes: Long,
    val violations: Long,
    /** Index of the input that hung (at most one: the run stops there). */
    val hangs: List<Long>,
    val failures: List<Failure>,
    val elapsed: Duration,
    val bytes: Long,
    val frames: Long,
    val refused: Long,
    val mutations: Map<Mutation, Long>,
) {
    /** Whether all [requested] inputs ran with no escape, violation or hang. */
    val clean: Boolean get() = completed == requested && escapes == 0L && violations == 0L && hangs.isEmpty()

    /** Inputs per second of wall-clock time (a benchmark figure, never asserted). */
    val inputsPerSecond: Double get() = completed / elapsed.toDouble(DurationUnit.SECONDS).coerceAtLeast(1e-9)

    /** One failing input: its index, how it was made, what came out, and its first bytes. */
    public data class Failure(val index: Long, val mutation: Mutation, val error: String, val input: ByteArray) {
        override fun toString(): String =
            "input #$index ($mutation): $error; bytes ${input.joinToString("") { "%02x".format(it) }}"
    }

    override fun toString(): String = buildString {
        append("$target: $completed/$requested inputs (seed $seed) in $elapsed, ${"%.0f".format(inputsPerSecond)}/s; ")
        append("escapes $escapes, violations $violations, hangs ${hangs.size}; frames $frames, refused $refused, bytes $bytes")
        failures.forEach { append("\n  ").append(it) }
    }
}
