package pod.mavlink.fuzz

import kotlin.random.Random
import kotlin.time.Duration
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.Duration.Companion.seconds

/**
 * Runs [inputs] inputs of a [FuzzTarget] from [seed] on a thread of its own, watched: an input that
 * has not finished after [stuckAfter] is reported as a hang and the run ends there (the stuck thread
 * is a daemon and is abandoned). [stuckAfter] is far beyond what any input needs (microseconds): it
 * tells a stuck decoder from a slow machine without asserting anything about speed.
 *
 * Every exception out of the target is counted: [FuzzViolation]s as violated properties, anything
 * else as an escape; the first [keepFailures] are kept with the input that caused them. Input `i`
 * draws from `Random(seed, i)`, so the same seed runs the same inputs.
 */
public class FuzzRun(
    private val target: FuzzTarget,
    private val seed: Long,
    private val inputs: Long,
    private val stuckAfter: Duration = 60.seconds,
    private val keepFailures: Int = 5,
) {
    init {
        require(inputs >= 0) { "inputs must be ≥ 0, was $inputs" }
        require(stuckAfter.isPositive()) { "stuckAfter must be positive, was $stuckAfter" }
    }

    @Volatile private var index = 0L
    @Volatile private var startedAt = 0L
    @Volatile private var done = false
    @Volatile private var abandoned = false

    private val tally = FuzzTally()
    private val failures = mutableListOf<FuzzReport.Failure>()
    private var escapes = 0L
    private var violations = 0L

    /** Runs the inputs and returns what happened; returns early only on a hang. */
    public fun run(): FuzzReport {
        val began = System.nanoTime()
        val worker = Thread({ work() }, "fuzz-${target.name}").apply { isDaemon = true }
        startedAt = System.nanoTime()
        worker.start()
        var hang: Long? = null
        val poll = minOf(stuckAfter.inWholeMilliseconds / 4, 250L).coerceAtLeast(1L)
        while (true) {
            worker.join(poll)
            if (!worker.isAlive) break
            if ((System.nanoTime() - startedAt).nanoseconds > stuckAfter && !done) {
                hang = index
                abandoned = true
                break
            }
        }
        val elapsed = (System.nanoTime() - began).nanoseconds
        val completed = if (hang != null) hang else index
        // The worker wrote these before its last index update (or is stuck and writes no more).
        return synchronized(failures) {
            FuzzReport(
                target = target.name, seed = seed, requested = inputs, completed = completed,
                escapes = escapes, violations = violations, hangs = listOfNotNull(hang), failures = failures.toList(),
                elapsed = elapsed, bytes = tally.bytes, frames = tally.frames, refused = tally.refused,
                mutations = Mutation.entries.associateWith { tally.mutations[it.ordinal] },
            )
        }
    }

    private fun work() {
        var i = 0L
        while (i < inputs && !abandoned) {
            startedAt = System.nanoTime()
            index = i
            try {
                target.runOne(Random(mix(seed, i)), tally)
            } catch (failure: Throwable) {
                synchronized(failures) {
                    if (failure is FuzzViolation) violations++ else escapes++
                    if (failures.size < keepFailures) failures += FuzzReport.Failure(i, tally.lastMutation, failure.toString(), tally.lastInput.copyOf(minOf(tally.lastInput.size, 600)))
                }
            }
            i++
        }
        synchronized(failures) { index = i }
        done = true
    }

    public companion object {
        /** The seed of input [index] of a run seeded [seed]: SplitMix64's finaliser, so neighbouring inputs are unrelated. */
        public fun mix(seed: Long, index: Long): Long {
            var z = seed + (index + 1) * -0x61c8864680b583ebL
            z = (z xor (z ushr 30)) * -0x40a7b892e31b1a47L
            z = (z xor (z ushr 27)) * -0x6b2fb644ecceee15L
            return z xor (z ushr 31)
        }
    }
}
