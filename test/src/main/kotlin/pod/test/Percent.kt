package pod.test

/**
 * A share of something, as people say it in a test: `loss(20.percent)`. Kept in pod-test because
 * the only share Pod's own API takes is a probability (a [Double] in 0..1, as
 * [pod.sim.fault.LinkFaults.drop]), which [fraction] gives.
 */
@JvmInline
public value class Percent(
    /** The share in percent, 0..100. */
    public val value: Double,
) : Comparable<Percent> {
    init {
        // Written as a positive range check so that NaN fails too.
        require(value in 0.0..100.0) { "percent must be in 0..100, was $value" }
    }

    /** The share as a probability, 0..1. */
    public val fraction: Double get() = value / 100.0

    override fun compareTo(other: Percent): Int = value.compareTo(other.value)

    override fun toString(): String = "$value %"
}

/** This many percent: `20.percent`. */
public val Number.percent: Percent get() = Percent(toDouble())
