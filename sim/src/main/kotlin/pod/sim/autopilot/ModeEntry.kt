package pod.sim.autopilot

import pod.sim.flight.MultirotorAirframe
import pod.sim.flight.moved
import kotlin.math.cos
import kotlin.math.sin

/**
 * What entering a mode makes the vehicle do, from the mode's [Behaviour] in the vehicle's
 * profile, with nobody on the sticks. The branches on [pod.sim.autopilot.profile.AutopilotProfile.rotorcraft]
 * are the airframe's, not a firmware's: a multirotor with its throttle at minimum drops, a plane
 * keeps flying; a multirotor holds by hovering, a plane by circling.
 */
internal class ModeEntry(private val ap: FlightControl) {
    private val profile get() = ap.profile

    /** What the vehicle does on entering mode [name] (AUTO starts the mission). */
    fun activityFor(name: String): Activity {
        val flying = ap.flying
        val body = ap.body
        val alt = body.location.altitude.meters
        return when (profile.behaviour(name) ?: Behaviour.HOLD) {
            Behaviour.MANUAL -> when {
                !flying -> Activity.Parked
                // Throttle at minimum with the motors passing it through (ArduCopter
                // mode_stabilize.cpp ModeStabilize::run: get_pilot_desired_throttle): it drops.
                profile.rotorcraft -> Activity.Descending(null, MultirotorAirframe.FALL_SPEED)
                else -> Activity.Cruise(body.heading, alt)
            }
            Behaviour.STICK_CLIMB_RATE -> when {
                !flying -> Activity.Parked
                profile.rotorcraft -> Activity.Descending(body.location.takeIf { profile.stickModeHoldsPosition(name) }, profile.pilotDescentRate(ap.params))
                else -> holdHere()
            }
            Behaviour.HOLD, Behaviour.GUIDED -> if (flying) holdHere(profile.holdBraking(name)) else Activity.Parked
            Behaviour.CIRCLE -> if (!flying) {
                Activity.Parked
            } else if (profile.rotorcraft) {
                val (r, clockwise) = profile.circleMode(ap.params)
                val h = Math.toRadians(body.heading)
                Activity.Hold(moved(body.location, cos(h) * r, sin(h) * r, 0.0), r, clockwise)
            } else {
                holdHere()
            }
            Behaviour.AUTO -> {
                ap.mission.start()
                Activity.Mission
            }
            Behaviour.RTL -> if (flying) Activity.Returning(ap.returnPlan()) else Activity.Parked
            Behaviour.LAND -> if (flying) Activity.Landing(landingSpot()) else Activity.Parked
            Behaviour.TAKEOFF -> {
                val target = ap.takeoffAltitude(null)
                when {
                    flying && alt >= target - 1 -> holdHere()
                    else -> Activity.Takeoff(target, profile.afterTakeoffMode)
                }
            }
        }
    }

    /** Where a LAND here touches down: a multirotor descends where it stops (null), a plane glides to this point. */
    fun landingSpot() = if (profile.rotorcraft) null else ap.body.location

    /**
     * Holding here: a multirotor hovers where it stops, braking at [braking] m/s² (null: its own
     * acceleration limit), not where it was when told (it would overshoot and fly back); a plane
     * circles at the loiter radius. ArduCopter BRAKE stops at BRAKE_MODE_DECEL_RATE
     * (ArduCopter/mode_brake.cpp ModeBrake::init: the position controller's stopping point at that
     * deceleration); GUIDED's entry holds the waypoint controller's stopping point
     * (ArduCopter/mode_guided.cpp ModeGuided::init); PX4 Hold the braking position
     * (src/modules/navigator/loiter.cpp Loiter::on_activation, set_loiter_position from the
     * multicopter's stopping point, MPC_ACC_HOR).
     */
    fun holdHere(braking: Double? = null): Activity {
        val body = ap.body
        return if (profile.rotorcraft) {
            val a = braking ?: ap.performance().acceleration
            val speed = kotlin.math.hypot(body.velocityNorth, body.velocityEast)
            val distance = speed * speed / (2 * a)
            val stop = if (speed < 0.1) body.location else moved(body.location, body.velocityNorth / speed * distance, body.velocityEast / speed * distance, 0.0)
            Activity.Hold(stop, 0.0, braking = braking)
        } else {
            ap.loiterRadius().let { (r, cw) -> Activity.Hold(body.location, r, cw) }
        }
    }
}
