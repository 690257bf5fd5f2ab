package pod.sim.autopilot

import pod.core.units.Location

/** What the vehicle is doing, whatever its mode is called. */
internal sealed interface Activity {
    /** On the ground. */
    data object Parked : Activity

    /** Climbing to [altitude] (AMSL), then switching to mode [then] (or holding where it is). */
    data class Takeoff(val altitude: Double, val then: String?) : Activity

    /**
     * Holding at [center]: hover, or circle at [radius]. [braking], when given, is the deceleration
     * (m/s²) a multirotor stops with on its way there (ArduCopter BRAKE's), instead of its own.
     */
    data class Hold(val center: Location, val radius: Double, val clockwise: Boolean = true, val braking: Double? = null) : Activity

    /**
     * Flying to [target] at [speed] m/s (null: cruise), then holding there: a multirotor hovers, a
     * plane circles it at [radius] m ([clockwise] or not; radius 0: its loiter radius and direction).
     * An ArduPlane more than three loiter radii away flies the line from [from] (where it was when
     * the command came) to [target] first (ArduPlane/navigation.cpp Plane::update_loiter: GUIDED
     * with crosstrack, loiter point not reached, farther than 3 × radius → update_waypoint from
     * prev_WP_loc, which Plane::set_guided_WP sets to the current location).
     */
    data class GoTo(val target: Location, val speed: Double?, val radius: Double = 0.0, val clockwise: Boolean = true, val from: Location? = null) : Activity

    /**
     * A multirotor orbiting [center] at [radius] m, [clockwise] or not, at [speed] m/s along the
     * circle (PX4's orbit mode after DO_ORBIT).
     */
    data class Orbit(val center: Location, val radius: Double, val clockwise: Boolean, val speed: Double) : Activity

    /** Returning to launch. */
    data class Returning(val plan: ReturnPlan) : Activity

    /** Landing (over [at] when given). */
    data class Landing(val at: Location?) : Activity

    /** Flying the mission. */
    data object Mission : Activity

    /** Flying straight on [heading] at [altitude]. */
    data class Cruise(val heading: Double, val altitude: Double) : Activity

    /** Descending at [rate] m/s (over [over], or wherever it stops) until it touches down; then parked. */
    data class Descending(val over: Location?, val rate: Double) : Activity
}
