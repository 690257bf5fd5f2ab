package pod.core.workflow

import pod.core.units.Distance
import kotlin.math.abs

/**
 * When a survey flies over rising or falling ground, the height above ground a rangefinder measures
 * drifts from the [target]; once it is off by more than [tolerance] for [confirmations] readings in
 * a row, the remaining waypoints move up or down by the difference, within [minimum] and [maximum]
 * (heights above home), and the flight goes on from the current waypoint without landing.
 */
public class AltitudeCorrection(
    /** The height above ground the survey is meant to fly at. */
    public val target: Distance,
    /** How far the measured height may drift before the waypoints move. */
    public val tolerance: Distance,
    /** The lowest altitude above home a corrected waypoint may have. */
    public val minimum: Distance,
    /** The highest altitude above home a corrected waypoint may have. */
    public val maximum: Distance,
    /** How many readings in a row must be off before a correction (one outlier does nothing). */
    public val confirmations: Int = 3,
) {
    init {
        require(target.meters > 0 && target.meters.isFinite()) { "target must be a positive height above ground, was $target" }
        require(tolerance.meters > 0 && tolerance.meters.isFinite()) { "tolerance must be positive, was $tolerance" }
        require(minimum.meters > 0 && minimum <= maximum && maximum.meters.isFinite()) { "minimum and maximum must satisfy 0 < minimum ≤ maximum, were $minimum and $maximum" }
        require(confirmations >= 1) { "confirmations must be ≥ 1, was $confirmations" }
    }

    private var offReadings = 0

    /**
     * Takes a [measured] height above ground while flying at [altitude] above home; returns the
     * change to apply to the remaining waypoints' altitude, or null when none is due. The change is
     * what puts the vehicle back at [target] above this ground, cut so that [altitude] plus it stays
     * within [minimum]..[maximum]; a change cut to nothing is null.
     */
    public fun reading(measured: Distance, altitude: Distance): Distance? {
        val error = target.meters - measured.meters
        if (!measured.meters.isFinite() || abs(error) <= tolerance.meters) {
            offReadings = 0
            return null
        }
        if (++offReadings < confirmations) return null
        offReadings = 0
        val corrected = (altitude.meters + error).coerceIn(minimum.meters, maximum.meters)
        val change = corrected - altitude.meters
        return if (abs(change) < 1e-6) null else Distance(change)
    }
}
