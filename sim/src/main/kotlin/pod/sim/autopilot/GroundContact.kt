package pod.sim.autopilot

import pod.core.vehicle.LandedState
import pod.core.vehicle.Severity
import pod.sim.flight.Guidance

/**
 * What happens to a vehicle on the ground, or that meets it: an armed vehicle standing still
 * disarms itself after its profile's delay ([AutopilotProfile.autoDisarmDelay]), and one that
 * flies into the terrain crashes.
 */
internal class GroundContact(private val ap: FlightControl) {
    private var disarmAt: Double? = null

    /** The vehicle touched down at the end of a landing (the disarm delay after a landing applies). */
    var landedByLanding = false

    /**
     * What the simulator did to a vehicle it saw fly into the ground, or null: flying on (not
     * climbing out of a take-off, not landing) lower than [TERRAIN_CLEARANCE] above the ground
     * while moving over it. Not an autopilot's behaviour but the world's: the vehicle disarms and
     * drops, saying "Crash: flew into terrain" (CRITICAL), so a ground station that sends a vehicle
     * along the ground sees its flight fail instead of a track that no real vehicle could fly.
     */
    var crashed: String? = null
        private set

    /** The vehicle armed: a new flight. */
    fun armed() {
        landedByLanding = false
        disarmAt = null
    }

    /** The vehicle disarmed. */
    fun disarmed() {
        disarmAt = null
    }

    /** Ends the flight of a vehicle that flew into the ground under [guidance]. */
    fun checkTerrainClearance(guidance: Guidance) {
        val body = ap.body
        if (!ap.armed || body.onGround || guidance is Guidance.Climb || guidance is Guidance.Land || guidance is Guidance.Glide) return
        val state = ap.landedState()
        if (state == LandedState.TAKEOFF || state == LandedState.LANDING) return
        val moving = kotlin.math.hypot(body.velocityNorth, body.velocityEast) > TERRAIN_MOVING_SPEED
        if (!moving || body.location.altitude.meters - ap.ground >= TERRAIN_CLEARANCE) return
        crashed = "flew into terrain"
        ap.text(Severity.CRITICAL, "Crash: flew into terrain")
        ap.fly(Activity.Parked)
        ap.disarm()
    }

    /** Disarms a vehicle parked armed once its profile's delay has passed. */
    fun autoDisarm() {
        val body = ap.body
        val activity = ap.activity
        val parked = ap.armed && body.onGround && body.airspeed < 0.1 && (activity == Activity.Parked || (activity == Activity.Mission && !ap.mission.wantsToFly()))
        if (!parked) {
            disarmAt = null
            if (!body.onGround) landedByLanding = false
            return
        }
        val at = disarmAt ?: run {
            val delay = ap.profile.autoDisarmDelay(ap.params, landedByLanding) ?: return
            (ap.time + delay).also { disarmAt = it }
        }
        if (ap.time >= at) {
            ap.disarm()
            ap.text(Severity.INFO, ap.profile.autoDisarmText)
        }
    }

    companion object {
        /** How high above the ground a vehicle flying away from a take-off or landing must stay, m. */
        const val TERRAIN_CLEARANCE = 1.0
        /** Over the ground faster than this, m/s, a vehicle counts as flying along it rather than hovering. */
        const val TERRAIN_MOVING_SPEED = 1.0
    }
}
