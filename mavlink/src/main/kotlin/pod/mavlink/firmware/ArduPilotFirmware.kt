package pod.mavlink.firmware

import pod.mavlink.param.ParamEncoding
import pod.mavlink.plan.MissionFlavor
import pod.mavlink.telemetry.ModeRole

/** What ArduPilot does the same on every airframe; [ArduCopter] and [ArduPlane] add the airframe. */
public sealed class ArduPilotFirmware : Firmware() {
    override val missionNeedsTakeOff: Boolean get() = true
    override val mayRefuseMissionClear: Boolean get() = true
    override val storesMissionPacked: Boolean get() = true
    override val paramEncoding: ParamEncoding get() = ParamEncoding.CAST
}

/** ArduPilot Copter (and the other ArduPilot airframes that are not fixed-wing). */
public data object ArduCopter : ArduPilotFirmware() {
    // The modes whose `allows_arming()` is false (ArduCopter/mode.h: AUTO unless AUTO_OPTIONS
    // allows it, RTL, SMART_RTL, AUTO_RTL, LAND, CIRCLE, BRAKE, FLIP, AUTOTUNE, FOLLOW, AVOID_ADSB).
    private val notArmable = setOf("AUTO", "RTL", "SMART_RTL", "AUTO_RTL", "LAND", "CIRCLE", "BRAKE", "FLIP", "AUTOTUNE", "FOLLOW", "AVOID_ADSB")

    override val missionFlavor: MissionFlavor get() = MissionFlavor.ARDUCOPTER
    override val fixedWing: Boolean get() = false
    override val takeOffWay: TakeOffWay get() = TakeOffWay.COMMAND_IN_GUIDED
    override val missionArmingRole: ModeRole get() = ModeRole.GUIDED
    override val pausesGuidedFlight: Boolean get() = true

    // ArduCopter takes NAV_TAKEOFF only in a mode with a user takeoff (Mode::do_user_takeoff,
    // has_user_takeoff in ArduCopter/mode.h: GUIDED, LOITER, POSHOLD, ZIGZAG; ALT_HOLD, SPORT and
    // FLOWHOLD only when the pilot navigates, which NAV_TAKEOFF's param3 = 0 rules out).
    override val takeOffCommandModes: Set<String> = setOf("GUIDED", "LOITER", "POSHOLD", "ZIGZAG")

    override fun armsIn(mode: String): Boolean = mode !in notArmable

    override fun modeFor(role: ModeRole): String = when (role) {
        // BRAKE: stops and holds position and altitude on its own (ArduCopter/mode_brake.cpp
        // ModeBrake::run: climb rate 0; init sets no timeout, which only failsafes set).
        // Never LOITER or POSHOLD: they take the climb rate from the throttle stick, so with
        // no transmitter (stick at minimum) they descend, land and disarm (mode_loiter.cpp
        // ModeLoiter::run, mode_poshold.cpp: get_pilot_desired_climb_rate). Not GUIDED
        // either: switching to GUIDED while in GUIDED changes nothing (mode.cpp
        // Copter::set_mode returns at once for the current mode), so a goto would go on.
        ModeRole.HOLD -> "BRAKE"
        ModeRole.GUIDED, ModeRole.TAKEOFF -> "GUIDED"
        ModeRole.MISSION -> "AUTO"
        ModeRole.RETURN -> "RTL"
        ModeRole.LAND -> "LAND"
    }
}

/** ArduPilot Plane. */
public data object ArduPlane : ArduPilotFirmware() {
    // RTL and the QuadPlane returns and landings (`_pre_arm_checks` in ArduPlane/mode.h,
    // "Arm: RTL mode not armable").
    private val notArmable = setOf("RTL", "QRTL", "QLAND", "LOITER_ALT_QLAND")

    override val missionFlavor: MissionFlavor get() = MissionFlavor.ARDUPLANE
    override val fixedWing: Boolean get() = true
    override val takeOffWay: TakeOffWay get() = TakeOffWay.TAKEOFF_MODE
    override val missionArmingRole: ModeRole get() = ModeRole.HOLD
    override val repositionTakesLoiterRadius: Boolean get() = true
    override val landsThroughLandingSequence: Boolean get() = true

    override fun armsIn(mode: String): Boolean = mode !in notArmable

    override fun modeFor(role: ModeRole): String? = when (role) {
        // ArduPlane LOITER circles where it is at the current altitude under automatic
        // throttle (ArduPlane/mode_loiter.cpp ModeLoiter::_enter: auto_throttle_mode,
        // do_loiter_at_location from the current location); the stick does not set the height.
        ModeRole.HOLD -> "LOITER"
        ModeRole.GUIDED -> "GUIDED"
        ModeRole.MISSION -> "AUTO"
        ModeRole.RETURN -> "RTL"
        ModeRole.LAND -> null
        ModeRole.TAKEOFF -> "TAKEOFF"
    }
}
