package pod.core.units

import kotlin.jvm.JvmInline

/** A speed, stored in metres per second. Build one with [mps]: `12.mps`. */
@JvmInline
public value class Speed(
    /** The speed in metres per second. */
    public val metersPerSecond: Double,
) : Comparable<Speed> {
    override fun compareTo(other: Speed): Int = metersPerSecond.compareTo(other.metersPerSecond)

    override fun toString(): String = "${metersPerSecond.format(1)} m/s"

    /** Speed constants; make speeds with [mps]. */
    public companion object {
        /** Standing still. */
        public val ZERO: Speed = Speed(0.0)
    }
}

/** This many metres per second. */
public val Number.mps: Speed get() = Speed(toDouble())
