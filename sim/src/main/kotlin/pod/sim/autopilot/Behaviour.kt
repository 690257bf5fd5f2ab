package pod.sim.autopilot

/** What a flight mode makes the simulated vehicle do; each profile maps its mode names onto these. */
internal enum class Behaviour {
    /** Manual or stabilised modes with nobody on the sticks: a plane flies straight; a multirotor's throttle is at minimum, so it falls. */
    MANUAL,
    /**
     * The throttle stick sets the climb rate (ArduCopter ALT_HOLD, LOITER, POSHOLD…): with nobody on
     * the sticks it is at minimum, so the multirotor descends at the pilot's maximum rate, lands
     * and disarms.
     */
    STICK_CLIMB_RATE,
    /** Hold position (multirotor) or circle here (plane). */
    HOLD,
    /** Guided: hold or go where DO_REPOSITION / NAV_TAKEOFF says. */
    GUIDED,
    /** Circle around a point. */
    CIRCLE,
    /** Fly the mission. */
    AUTO,
    /** Return home (and land, for multirotors; circle for planes). */
    RTL,
    /** Land here. */
    LAND,
    /** Take off and climb to the take-off altitude. */
    TAKEOFF,
}
