package pod.core.units

import kotlin.jvm.JvmInline
import kotlin.math.PI

/** An angle, stored in degrees. Build one with [deg]: `90.deg`. */
@JvmInline
public value class Angle(
    /** The angle in degrees. */
    public val degrees: Double,
) : Comparable<Angle> {
    /** The angle in radians. */
    public val radians: Double get() = degrees * PI / 180.0

    override fun compareTo(other: Angle): Int = degrees.compareTo(other.degrees)

    override fun toString(): String = "${degrees.format(1)}°"
}

/** This many degrees. */
public val Number.deg: Angle get() = Angle(toDouble())
