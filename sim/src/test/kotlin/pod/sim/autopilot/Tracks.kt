package pod.sim.autopilot

import pod.core.units.Location
import pod.sim.flight.northEast
import kotlin.math.hypot
import kotlin.math.roundToLong

/** A flown track as north/east metres from a centre, one point per simulated step. */
internal class Track(private val center: Location, private val points: List<Pair<Double, Double>>, private val speeds: List<Double>) {
    /** Mean horizontal distance from the centre, m. */
    val meanRadius: Double get() = points.map { (n, e) -> hypot(n, e) }.average()

    /** Smallest and largest horizontal distance from the centre, m. */
    val radiusRange: ClosedFloatingPointRange<Double> get() = points.minOf { (n, e) -> hypot(n, e) }..points.maxOf { (n, e) -> hypot(n, e) }

    /** Mean ground speed, m/s. */
    val meanSpeed: Double get() = speeds.average()

    /**
     * The signed area swept around the centre, m²: ½ Σ (nᵢ·eᵢ₊₁ − nᵢ₊₁·eᵢ) with x = north and
     * y = east. With that axis order a clockwise turn seen from above (north → east → south) is
     * positive and a counter-clockwise one negative.
     */
    val signedArea: Double get() = points.zipWithNext { (n1, e1), (n2, e2) -> n1 * e2 - n2 * e1 }.sum() / 2

    override fun toString(): String = "Track(around $center, mean radius $meanRadius, range $radiusRange, area $signedArea, speed $meanSpeed)"
}

/** Flies [seconds] of simulated time and returns the track around [center]. */
internal fun SimAutopilot.track(center: Location, seconds: Double): Track {
    val points = ArrayList<Pair<Double, Double>>()
    val speeds = ArrayList<Double>()
    run(seconds) {
        points += northEast(center, it.body.location)
        speeds += hypot(it.body.velocityNorth, it.body.velocityEast)
    }
    return Track(center, points, speeds)
}

/** DO_REPOSITION as COMMAND_INT in GLOBAL_RELATIVE_ALT_INT to [at], [relAlt] m above home. */
internal fun repositionInt(at: Location, relAlt: Double, param2: Float = 0f, param3: Float = 0f, param4: Float = 0f): CommandRequest =
    CommandRequest(
        192, param1 = -1f, param2 = param2, param3 = param3, param4 = param4,
        x = (at.latitude * 1e7).roundToLong().toDouble(), y = (at.longitude * 1e7).roundToLong().toDouble(), z = relAlt.toFloat(), frame = 6,
    )
