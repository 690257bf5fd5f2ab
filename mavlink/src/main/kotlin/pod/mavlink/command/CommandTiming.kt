package pod.mavlink.command

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * How long to wait for a vehicle's answers to commands.
 *
 * A command is resent (with `confirmation` counting up) whenever no COMMAND_ACK came within the
 * attempt timeout, which follows the measured round trip between [minAttemptTimeout] and
 * [maxAttemptTimeout]. While the vehicle keeps sending other messages the loss was on a live link,
 * and the command goes again after the same timeout, up to [quickResends] times; otherwise the
 * timeout grows by half on each resend, so a silent or swamped vehicle is not hammered. Pod gives
 * up when nothing at all came back for [timeout]. Resending on a short timer is what gets commands
 * through lossy links: at 30 % loss each way only half the round trips complete.
 */
public data class CommandTiming(
    /** Silence after which a command fails with [CommandTimeout]. */
    public val timeout: Duration = 10.seconds,
    /** Attempt timeout before any round trip was measured. */
    public val initialAttemptTimeout: Duration = 500.milliseconds,
    /** Shortest attempt timeout, however quick the link. */
    public val minAttemptTimeout: Duration = 50.milliseconds,
    /** Longest attempt timeout, after backing off. */
    public val maxAttemptTimeout: Duration = 1.seconds,
    /** Wait before resending a TEMPORARILY_REJECTED command. */
    public val retryDelay: Duration = 500.milliseconds,
    /** How long TEMPORARILY_REJECTED answers are retried before the command fails with them. */
    public val temporarilyRejectedFor: Duration = 5.seconds,
    /** Longest wait for the next answer after the vehicle said IN_PROGRESS. */
    public val inProgressTimeout: Duration = 30.seconds,
    /** Resends at the unchanged attempt timeout while the vehicle is heard, before backing off. */
    public val quickResends: Int = 8,
) {
    init {
        require(minAttemptTimeout.isPositive()) { "minAttemptTimeout must be > 0, was $minAttemptTimeout" }
        require(maxAttemptTimeout >= minAttemptTimeout) { "maxAttemptTimeout must be ≥ minAttemptTimeout ($minAttemptTimeout), was $maxAttemptTimeout" }
        require(initialAttemptTimeout in minAttemptTimeout..maxAttemptTimeout) {
            "initialAttemptTimeout must be in $minAttemptTimeout..$maxAttemptTimeout, was $initialAttemptTimeout"
        }
        require(timeout >= maxAttemptTimeout) { "timeout must be ≥ maxAttemptTimeout ($maxAttemptTimeout), was $timeout" }
        require(retryDelay.isPositive()) { "retryDelay must be > 0, was $retryDelay" }
        require(!temporarilyRejectedFor.isNegative()) { "temporarilyRejectedFor must be ≥ 0, was $temporarilyRejectedFor" }
        require(inProgressTimeout.isPositive()) { "inProgressTimeout must be > 0, was $inProgressTimeout" }
        require(quickResends in 0..100) { "quickResends must be in 0..100, was $quickResends" }
    }
}

/**
 * Smoothed command round trip of one vehicle (Jacobson/Karels, as TCP): the attempt timeout is
 * the smoothed round trip plus four deviations, within the [CommandTiming] bounds. Only answers to
 * a first send are sampled, since an answer after a resend cannot say which send it answers.
 */
internal class CommandRoundTrip(
    private val timing: CommandTiming,
    /** A floor the link sets now, in nanoseconds, above [CommandTiming.minAttemptTimeout] (a paced radio's; 0: none). */
    private val linkFloorNanos: () -> Long = { 0L },
) {
    private var smoothed = -1.0
    private var deviation = 0.0

    val attemptTimeoutNanos: Long
        get() {
            val estimate = if (smoothed < 0) timing.initialAttemptTimeout.inWholeNanoseconds.toDouble() else smoothed + 4 * deviation
            val floor = maxOf(timing.minAttemptTimeout.inWholeNanoseconds, linkFloorNanos()).coerceAtMost(timing.maxAttemptTimeout.inWholeNanoseconds)
            return estimate.toLong().coerceIn(floor, timing.maxAttemptTimeout.inWholeNanoseconds)
        }

    /**
     * How long the caller may poll for an answer instead of suspending ([pod.mavlink.HotWait]): on a
     * quick link (a smoothed round trip within half of [pod.mavlink.HotWait.MAX_BUDGET_NANOS]) the
     * smoothed round trip plus four deviations, at most that budget; 0 before any round trip was
     * measured and on slower links. The deviation does not decide: one late answer on a busy
     * machine would stop the polling for many commands.
     */
    val hotWaitNanos: Long
        get() {
            val max = pod.mavlink.HotWait.MAX_BUDGET_NANOS
            if (smoothed < 0 || smoothed > max / 2) return 0
            return (smoothed + 4 * deviation).toLong().coerceAtMost(max)
        }

    fun sample(nanos: Long) {
        val x = nanos.coerceAtLeast(0).toDouble()
        if (smoothed < 0) {
            smoothed = x
            deviation = x / 2
        } else {
            deviation = 0.75 * deviation + 0.25 * kotlin.math.abs(smoothed - x)
            smoothed = 0.875 * smoothed + 0.125 * x
        }
    }
}
