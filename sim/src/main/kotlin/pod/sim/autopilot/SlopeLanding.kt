package pod.sim.autopilot

import pod.core.vehicle.Severity
import java.util.Locale
import kotlin.math.atan
import kotlin.math.cos
import kotlin.math.max
import kotlin.math.sin
import pod.core.units.Location
import pod.sim.flight.Guidance
import pod.sim.flight.bearing
import pod.sim.flight.horizontalDistance
import pod.sim.flight.moved
import pod.sim.flight.northEast

/**
 * ArduPlane's standard glide-slope landing (AP_Landing_Slope.cpp) from [from], the previous
 * waypoint, to [land]: the slope is fixed when the landing starts, from the two waypoints' heights
 * and distance, whatever it is (type_slope_setup_landing_glide_slope announces it as "Landing
 * glide slope N degrees"). The plane follows the line, sinking no faster than TECS_SINK_MAX, and
 * keeps flying along it past the land point (type_slope_verify_land aims 200 m beyond it). It
 * flares below LAND_FLARE_ALT, or, past half the leg, within LAND_FLARE_SEC of the ground at its
 * sink rate; from then on the throttle is at minimum (AP_TECS::_update_height_demand demands only
 * TECS_LAND_SINK) and the simulated airframe glides down at [GLIDE_RATIO]. A steep slope therefore
 * flares high and touches down far past the land point, as ArduPlane SITL did (53°: flare at 52 m,
 * touchdown ~311 m past).
 */
internal class SlopeLanding(private val ap: FlightControl, private val from: Location, private val land: Location) {
    private val total = max(horizontalDistance(from, land), 1.0)
    private val course = if (horizontalDistance(from, land) < 1.0) ap.body.heading else bearing(from, land)
    private val slope = (from.altitude.meters - land.altitude.meters) / total
    private var flared = false

    /** The glide slope, in degrees below the horizon. */
    val slopeDegrees: Double = Math.toDegrees(atan(slope))

    /** What to fly now. */
    fun guidance(): Guidance {
        val body = ap.body
        val along = alongTrack(body.location)
        val height = body.location.altitude.meters - land.altitude.meters
        val sink = body.velocityDown
        if (!flared && (height <= ap.params["LAND_FLARE_ALT"] || (along > total / 2 && height <= sink * ap.params["LAND_FLARE_SEC"]))) {
            flared = true
            val text = String.format(Locale.ROOT, "Flare %.1fm sink=%.2f speed=%.1f dist=%.1f", height, sink, body.airspeed, horizontalDistance(body.location, land))
            ap.text(Severity.INFO, text)
        }
        // Steer for a point on the line ahead, so the plane converges on it and holds it past the land point.
        val aim = pointAt(along + LOOK_AHEAD_M)
        val heading = bearing(body.location, aim)
        return if (flared) {
            Guidance.Glide(heading, ap.ground - 1.0, max(ap.params["TECS_LAND_SINK"], body.airspeed / GLIDE_RATIO))
        } else {
            Guidance.Glide(heading, land.altitude.meters + slope * (total - along), ap.performance().descent)
        }
    }

    private fun alongTrack(at: Location): Double {
        val (n, e) = northEast(from, at)
        val c = Math.toRadians(course)
        return n * cos(c) + e * sin(c)
    }

    private fun pointAt(distance: Double): Location {
        val c = Math.toRadians(course)
        return moved(from, distance * cos(c), distance * sin(c), 0.0)
    }

    companion object {
        /** Power-off glide ratio of the simulated plane once the throttle is closed in the flare. */
        const val GLIDE_RATIO = 8.0
        private const val LOOK_AHEAD_M = 60.0
    }
}
