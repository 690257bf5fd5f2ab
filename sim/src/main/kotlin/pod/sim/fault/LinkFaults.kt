package pod.sim.fault

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds

/**
 * What goes wrong on one direction of a link, datagram by datagram. Probabilities are independent
 * per datagram; every argument is checked here, so a bad configuration fails where it is written
 * (`LinkFaults(drop = 1.5)` → "drop must be in 0..1, was 1.5").
 *
 * @see FaultModel
 */
public data class LinkFaults(
    /** Probability that a datagram is lost. */
    public val drop: Double = 0.0,
    /** Probability that a datagram that survives is delivered twice. */
    public val duplicate: Double = 0.0,
    /** Probability that a datagram that survives is held back until [reorderDepth] later ones have passed it. */
    public val reorder: Double = 0.0,
    /** How many later datagrams overtake a held one before it is released. */
    public val reorderDepth: Int = 1,
    /**
     * The longest a datagram is held for reordering: when traffic stops, a held datagram goes out
     * after this long instead of waiting forever (it then counts as reordered only if something
     * overtook it).
     */
    public val maxHold: Duration = 100.milliseconds,
    /** Fixed latency added to every datagram. */
    public val delay: Duration = Duration.ZERO,
    /** Extra latency drawn uniformly from 0 until this, per copy; unequal draws reorder datagrams as a real network would. */
    public val jitter: Duration = Duration.ZERO,
    /** Probability that a datagram that survives has one byte changed (XOR with a non-zero mask). */
    public val corrupt: Double = 0.0,
) {
    init {
        requireProbability("drop", drop)
        requireProbability("duplicate", duplicate)
        requireProbability("reorder", reorder)
        requireProbability("corrupt", corrupt)
        require(reorderDepth >= 1) { "reorderDepth must be ≥ 1, was $reorderDepth" }
        require(maxHold.isPositive() && maxHold.isFinite()) { "maxHold must be > 0 and finite, was $maxHold" }
        require(!delay.isNegative() && delay.isFinite()) { "delay must be ≥ 0 and finite, was $delay" }
        require(!jitter.isNegative() && jitter.isFinite()) { "jitter must be ≥ 0 and finite, was $jitter" }
    }

    /** Whether this configuration changes nothing: every datagram passes once, unchanged, at once and in order. */
    public val isNone: Boolean
        get() = drop == 0.0 && duplicate == 0.0 && reorder == 0.0 && corrupt == 0.0 &&
            delay == Duration.ZERO && jitter == Duration.ZERO

    /** A fault model with no faults. */
    public companion object {
        /** A perfect link. */
        public val None: LinkFaults = LinkFaults()

        private fun requireProbability(name: String, value: Double) {
            // Written as a positive range check so that NaN fails too.
            require(value in 0.0..1.0) { "$name must be in 0..1, was $value" }
        }
    }
}
