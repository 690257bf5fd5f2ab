package pod.test

import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.sin
import kotlin.math.sqrt
import kotlin.random.Random

/** A point drawn uniformly from the disc of [radius] metres around (0, 0), as (north, east) metres. */
internal fun Random.inDisc(radius: Double): Pair<Double, Double> {
    val r = radius * sqrt(nextDouble())
    val a = nextDouble(0.0, 2 * PI)
    return r * cos(a) to r * sin(a)
}

/** A double drawn uniformly from [range] (its start when the range is a single value). */
internal fun Random.within(range: ClosedFloatingPointRange<Double>): Double =
    if (range.start >= range.endInclusive) range.start else nextDouble(range.start, range.endInclusive)
