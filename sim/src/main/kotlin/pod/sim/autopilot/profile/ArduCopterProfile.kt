package pod.sim.autopilot.profile

import pod.mavlink.command.MavCommands.NAV_LOITER_TIME
import pod.mavlink.command.MavCommands.NAV_LOITER_TURNS
import pod.mavlink.command.MavCommands.NAV_LOITER_UNLIM
import pod.mavlink.command.MavCommands.NAV_SPLINE_WAYPOINT
import pod.mavlink.command.MavCommands.NAV_WAYPOINT
import pod.mavlink.command.CommandResult
import pod.mavlink.mission.MissionItem
import pod.sim.autopilot.Behaviour
import pod.sim.autopilot.ParamDef
import pod.sim.autopilot.ParamTables
import pod.sim.autopilot.SimParameters
import pod.sim.autopilot.SpeedOverrides
import pod.sim.flight.Performance

/** ArduCopter 4.7 on a multirotor. */
internal data object ArduCopterProfile : ArduPilotProfile() {
    override val rotorcraft: Boolean get() = true
    override val bootMode: String get() = "STABILIZE"

    // ArduCopter/mode.h: the modes whose allows_arming() is false (BRAKE included: a copter left in
    // BRAKE by a ground station's hold will not arm, "Arm: Mode not armable").
    private val notArmable = setOf("AUTO", "AUTO_RTL", "RTL", "SMART_RTL", "LAND", "CIRCLE", "FLIP", "AUTOTUNE", "AVOID_ADSB", "FOLLOW", "BRAKE")

    /**
     * ArduCopter's modes whose requires_GPS() is true (ArduCopter/mode.h): Copter::set_mode refuses
     * them until the estimator has a position ("Mode change to GUIDED failed: requires position",
     * ArduCopter/mode.cpp), while STABILIZE, ALT_HOLD and LAND need none.
     */
    private val needPosition = setOf("AUTO", "GUIDED", "LOITER", "RTL", "CIRCLE", "DRIFT", "POSHOLD", "BRAKE", "THROW", "SMART_RTL", "FOLLOW", "ZIGZAG", "AUTO_RTL")

    override fun behaviour(name: String): Behaviour = when (name) {
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

    /** AUTO_OPTIONS bit 0 allows arming in AUTO (ArduCopter/mode_auto.cpp ModeAuto::allows_arming). */
    override fun armable(name: String, params: SimParameters): Boolean =
        name !in notArmable || (name == "AUTO" && autoOptions(params) and 1 != 0)

    override fun needsPosition(name: String): Boolean = name in needPosition
    /** GUIDED, LOITER and POSHOLD take off (Mode::allows_takeoff... do_user_takeoff); the mode then holds. */
    override val takeoffModes: Set<String> = setOf("GUIDED", "LOITER", "POSHOLD")

    /** ArduCopter refuses DO_REPOSITION outside GUIDED before it looks at the location (DENIED). */
    override val repositionOutsideGuidedFirst: CommandResult get() = CommandResult.DENIED

    /** A destination outside the fence is refused before any mode change: FAILED. */
    override val repositionOutsideFence: CommandResult get() = CommandResult.FAILED

    override val landMode: String get() = "LAND"
    override val landStartMode: String get() = "AUTO_RTL"
    override val afterTakeoffMode: String? get() = null

    /** ArduCopter BRAKE stops at BRAKE_MODE_DECEL_RATE (ArduCopter/mode_brake.cpp ModeBrake::init). */
    override fun holdBraking(name: String): Double? = if (name == "BRAKE") BRAKE_DECELERATION else null

    override fun modeNotArmableText(name: String): String = "Arm: Mode not armable"

    /** ArduCopter refuses AUTO armed on the ground without a take-off item ("Auto: Missing Takeoff Cmd"). */
    override val autoNeedsTakeoffItemOnGround: Boolean get() = true
    override val loiterUnlimitedMode: String get() = "LOITER"

    /** GCS_MAVLINK_Copter::handle_command_pause_continue (see PauseContinue). */
    override val handlesPauseContinue: Boolean get() = true

    /**
     * ArduCopter ends a mission on a NAV_LAND with no take-off after it by disarming at touchdown
     * (ModeAuto::verify_land), and AP_Arming_Copter::disarm calls mission.reset().
     */
    override val disarmsAfterFinalLanding: Boolean get() = true

    private val zeroAltitudeItems = setOf(NAV_WAYPOINT, NAV_SPLINE_WAYPOINT, NAV_LOITER_UNLIM, NAV_LOITER_TIME, NAV_LOITER_TURNS)

    /**
     * ArduCopter fills in its current altitude for a NAV_WAYPOINT, spline or loiter item with
     * z = 0, wherever the item points (ArduCopter/mode_auto.cpp, `ModeAuto::loc_from_cmd`: "use
     * current altitude if not provided", called from `do_nav_wp` and `do_circle`;
     * `do_loiter_unlimited` the same for LOITER_UNLIM and LOITER_TIME).
     */
    override fun zeroAltitudeMeansCurrent(item: MissionItem): Boolean = item.command in zeroAltitudeItems

    override fun performance(params: SimParameters, overrides: SpeedOverrides): Performance = Performance(
        cruise = overrides.cruise ?: (params["WPNAV_SPEED"] / 100), climb = overrides.climb ?: (params["WPNAV_SPEED_UP"] / 100),
        descent = overrides.descent ?: (params["WPNAV_SPEED_DN"] / 100), landSpeed = params["LAND_SPEED"] / 100,
        acceleration = params["WPNAV_ACCEL"] / 100, circleRate = kotlin.math.abs(params["CIRCLE_RATE"]).coerceAtLeast(1.0),
    )

    override fun loiterCircle(params: SimParameters): Pair<Double, Boolean> = 0.0 to true
    override fun defaultAcceptanceRadius(params: SimParameters): Double = params["WPNAV_RADIUS"] / 100

    /** Pod's ArduCopter take-off height when a take-off names none, m. */
    override fun defaultTakeoffHeight(params: SimParameters): Double = 2.5

    /** One second after a landing, else DISARM_DELAY (0: never) (ArduCopter/motors.cpp auto_disarm_check). */
    override fun autoDisarmDelay(params: SimParameters, afterLanding: Boolean): Double? =
        if (afterLanding) 1.0 else params["DISARM_DELAY"].takeIf { it > 0 }

    override val autoDisarmText: String get() = "Disarming motors"

    /** RTL climbs to RTL_ALT (cm above home) or stays higher, then lands at home; it never descends before home. */
    override fun returnAltitude(params: SimParameters, homeAlt: Double, alt: Double): Triple<Double, Double, Boolean> =
        Triple(maxOf(homeAlt + params["RTL_ALT"] / 100, alt), 0.0, true)

    /**
     * How fast an ArduCopter descends with the throttle stick at minimum, m/s: PILOT_SPEED_DN, or
     * PILOT_SPEED_UP when that is 0 (ArduCopter/Attitude.cpp Copter::get_pilot_speed_dn).
     */
    override fun pilotDescentRate(params: SimParameters): Double = params["PILOT_SPEED_DN"].takeIf { it > 0 }.let { it ?: params["PILOT_SPEED_UP"] } / 100

    /**
     * ALT_HOLD controls no horizontal position (ArduCopter/mode_althold.cpp: the pilot's lean
     * angles, zero with no sticks), so it sinks wherever it stops; LOITER and POSHOLD hold theirs.
     */
    override fun stickModeHoldsPosition(name: String): Boolean = name != "ALT_HOLD"

    /** CIRCLE_RADIUS (cm) around the point ahead, clockwise when CIRCLE_RATE ≥ 0 (AC_Circle). */
    override fun circleMode(params: SimParameters): Pair<Double, Boolean> = params["CIRCLE_RADIUS"] / 100 to (params["CIRCLE_RATE"] >= 0)

    override fun parameters(systemId: Int): List<ParamDef> = ParamTables.arduCopter(systemId)

    /** DISARM_DELAY 0 keeps it armed on the ground. */
    override val keepArmedOnGround: Pair<String, Double> get() = "DISARM_DELAY" to 0.0

    /**
     * Nothing but HEARTBEAT: its SRn_ stream rates default to 0 (ArduPilot
     * libraries/GCS_MAVLink/GCS_MAVLink_Parameters.cpp, AP_MAV_DEFAULT_STREAM_RATE_* for
     * APM_BUILD_COPTER_OR_HELI).
     */
    override val streamDefaults: Map<Int, Double> get() = emptyMap()

    /** ArduCopter BRAKE's deceleration, m/s² (BRAKE_MODE_DECEL_RATE, 750 cm/s², ArduCopter/config.h). */
    const val BRAKE_DECELERATION = 7.5
}
