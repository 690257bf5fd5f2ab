package pod.e2e

import kotlin.math.roundToLong
import pod.core.units.Location
import pod.core.units.m

/** [this] moved [north] and [east] metres at [height] above home, on the wire's 10⁻⁷° grid. */
internal fun Location.at(north: Int, east: Int, height: Double): Location =
    offset(north.m, east.m).let { Location((it.latitude * 1e7).roundToLong() / 1e7, (it.longitude * 1e7).roundToLong() / 1e7, height.m) }
