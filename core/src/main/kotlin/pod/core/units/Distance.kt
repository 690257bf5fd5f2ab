package pod.core.units

import kotlin.jvm.JvmInline

/** A length, stored in metres. Build one with [m] or [km]: `15.m`, `2.km`. */
@JvmInline
public value class Distance(
    /** The length in metres. */
    public val meters: Double,
) : Comparable<Distance> {
    override fun compareTo(other: Distance): Int = meters.compareTo(other.meters)

    /** Sum of two lengths. */
    public operator fun plus(other: Distance): Distance = Distance(meters + other.meters)

    /** Difference of two lengths. */
    public operator fun minus(other: Distance): Distance = Distance(meters - other.meters)

    /** This length scaled by [factor]. */
    public operator fun times(factor: Double): Distance = Distance(meters * factor)

    /** The same length the other way (a negative offset north is one south). */
    public operator fun unaryMinus(): Distance = Distance(-meters)

    override fun toString(): String = "${meters.format(1)} m"

    /** Distance constants; make distances with [m], [mm] and [km]. */
    public companion object {
        /** Zero metres. */
        public val ZERO: Distance = Distance(0.0)
    }
}

/** This many metres. */
public val Number.m: Distance get() = Distance(toDouble())

/** This many millimetres (camera sensor sizes and focal lengths). */
public val Number.mm: Distance get() = Distance(toDouble() / 1000.0)

/** This many kilometres. */
public val Number.km: Distance get() = Distance(toDouble() * 1000.0)

internal fun Double.format(decimals: Int): String {
    var scale = 1.0
    repeat(decimals) { scale *= 10 }
    val rounded = kotlin.math.round(this * scale) / scale
    return rounded.toString()
}
