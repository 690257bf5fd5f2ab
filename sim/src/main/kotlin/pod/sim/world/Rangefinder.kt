package pod.sim.world

import pod.core.units.Distance
import pod.core.units.m

/**
 * A downward-facing lidar (MAV_SENSOR_ROTATION_PITCH_270) measuring the height above the terrain
 * below the vehicle. The defaults are a Benewake TF02-Pro (0.1–40 m, 100 Hz), which ArduPilot reads
 * with its Benewake driver (RNGFND1_TYPE = 19, RNGFND1_MIN / RNGFND1_MAX from the datasheet).
 */
public data class Rangefinder(
    /** The shortest distance it measures. */
    public val minDistance: Distance = 0.1.m,
    /** The longest distance it measures. */
    public val maxDistance: Distance = 40.m,
) {
    init {
        require(minDistance.meters >= 0) { "minDistance must be ≥ 0, was $minDistance" }
        require(maxDistance.meters > minDistance.meters) { "maxDistance must be > minDistance, was $maxDistance ≤ $minDistance" }
    }

    /**
     * What the autopilot reports for a true distance of [metres]: the distance itself, or beyond
     * [maxDistance] the out-of-range value ArduPilot's Benewake driver substitutes when the lidar
     * sees nothing, the configured maximum + 1 m (AP_RangeFinder_Benewake::get_reading:
     * MAX(model limit, max_distance_cm() + BENEWAKE_OUT_OF_RANGE_ADD_CM), the TF02 model limit being
     * 22 m). PX4 forwards what its driver publishes; the simulator sends the same value for both.
     */
    internal fun reading(metres: Double): Double = when {
        metres > maxDistance.meters -> maxDistance.meters + OUT_OF_RANGE_ADD_M
        else -> metres.coerceAtLeast(0.0)
    }

    internal companion object {
        const val OUT_OF_RANGE_ADD_M = 1.0
    }
}
