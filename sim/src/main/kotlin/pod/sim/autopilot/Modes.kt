package pod.sim.autopilot

import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType

/** What a flight mode makes the simulated vehicle do. */
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

/** Flight-mode semantics per autopilot flavour; names and numbers come from FlightModes. */
internal object Modes {
    private val planeNotArmable = setOf("RTL", "QRTL", "QLAND", "LOITER_ALT_QLAND")
    // ArduCopter/mode.h: the modes whose allows_arming() is false (BRAKE included: a copter left in
    // BRAKE by a ground station's hold will not arm, "Arm: Mode not armable").
    private val copterNotArmable = setOf("AUTO", "AUTO_RTL", "RTL", "SMART_RTL", "LAND", "CIRCLE", "FLIP", "AUTOTUNE", "AVOID_ADSB", "FOLLOW", "BRAKE")

    /**
     * ArduCopter's modes whose requires_GPS() is true (ArduCopter/mode.h): Copter::set_mode refuses
     * them until the estimator has a position ("Mode change to GUIDED failed: requires position",
     * ArduCopter/mode.cpp), while STABILIZE, ALT_HOLD and LAND need none.
     */
    private val copterNeedsPosition = setOf("AUTO", "GUIDED", "LOITER", "RTL", "CIRCLE", "DRIFT", "POSHOLD", "BRAKE", "THROW", "SMART_RTL", "FOLLOW", "ZIGZAG", "AUTO_RTL")

    /** Whether ArduCopter refuses mode [name] while its estimator has no position. */
    fun needsPosition(autopilot: Autopilot, type: VehicleType, name: String): Boolean =
        autopilot != Autopilot.PX4 && type.isMultirotor && name in copterNeedsPosition

    /** The behaviour of mode [name], or null when the simulated airframe cannot fly it. */
    fun behaviour(autopilot: Autopilot, type: VehicleType, name: String): Behaviour? = when {
        autopilot == Autopilot.PX4 -> when (name) {
            "MANUAL", "STABILIZED", "ACRO", "RATTITUDE", "ALTCTL" -> Behaviour.MANUAL
            // POSCTL.ORBIT: OrbitCommand sets the circle; entered otherwise it holds here.
            "POSCTL", "OFFBOARD", "AUTO.LOITER", "AUTO.READY", "AUTO.FOLLOW_TARGET", "POSCTL.ORBIT" -> Behaviour.HOLD
            "AUTO.MISSION" -> Behaviour.AUTO
            "AUTO.RTL" -> Behaviour.RTL
            "AUTO.LAND", "AUTO.PRECLAND" -> Behaviour.LAND
            "AUTO.TAKEOFF" -> Behaviour.TAKEOFF
            else -> null
        }
        type.isMultirotor -> when (name) {
            // The simulator has no transmitter, as a vehicle flown only by a ground station: the
            // throttle stick reads minimum (SITL's RC3 = 1000). ArduCopter's ALT_HOLD, LOITER,
            // POSHOLD, SPORT, FLOWHOLD and ZIGZAG turn it into a climb rate
            // (ArduCopter/mode_loiter.cpp ModeLoiter::run, mode_poshold.cpp ModePosHold::run,
            // mode_althold.cpp ModeAltHold::run: get_pilot_desired_climb_rate(throttle) limited to
            // -get_pilot_speed_dn()); STABILIZE, ACRO and DRIFT pass it to the motors as it is.
            "ALT_HOLD", "LOITER", "POSHOLD", "SPORT", "FLOWHOLD", "ZIGZAG" -> Behaviour.STICK_CLIMB_RATE
            "STABILIZE", "ACRO", "DRIFT" -> Behaviour.MANUAL
            "AUTO", "AUTO_RTL" -> Behaviour.AUTO
            "GUIDED", "GUIDED_NOGPS" -> Behaviour.GUIDED
            "CIRCLE" -> Behaviour.CIRCLE
            "RTL", "SMART_RTL" -> Behaviour.RTL
            "LAND" -> Behaviour.LAND
            else -> Behaviour.HOLD
        }
        else -> when {
            name == "AUTO" -> Behaviour.AUTO
            name == "RTL" -> Behaviour.RTL
            name == "LOITER" -> Behaviour.HOLD
            name == "CIRCLE" -> Behaviour.CIRCLE
            name == "GUIDED" -> Behaviour.GUIDED
            name == "TAKEOFF" -> Behaviour.TAKEOFF
            name.startsWith("Q") || name == "LOITER_ALT_QLAND" -> null // not a QuadPlane
            else -> Behaviour.MANUAL
        }
    }

    /** Why arming in mode [name] is refused, or null when the mode allows arming. */
    fun armable(autopilot: Autopilot, type: VehicleType, name: String, autoOptions: Int): Boolean = when {
        // Orbit prevents arming too (ModeUtil/mode_requirements.cpp: mode_req_prevent_arming).
        autopilot == Autopilot.PX4 -> name !in setOf("AUTO.RTL", "AUTO.LAND", "POSCTL.ORBIT")
        type.isMultirotor -> name !in copterNotArmable || (name == "AUTO" && autoOptions and 1 != 0)
        // ArduPlane's ModeRTL (and the QuadPlane returns and landings) refuse arming in _pre_arm_checks (ArduPlane/mode.h).
        else -> name !in planeNotArmable
    }
}
