package pod.sim.autopilot.profile

import pod.mavlink.MessageIds
import pod.mavlink.mission.MissionItem
import pod.core.units.Location
import pod.mavlink.command.CommandResult
import pod.sim.autopilot.Activity
import pod.sim.autopilot.Behaviour
import pod.sim.autopilot.CommandRequest
import pod.sim.autopilot.FlightControl
import pod.sim.autopilot.ParamDef
import pod.sim.autopilot.ParamTables
import pod.sim.autopilot.SimParameters
import pod.sim.autopilot.SpeedOverrides
import pod.sim.flight.Performance

/** ArduPlane 4.7 on a fixed wing (not a QuadPlane). */
internal data object ArduPlaneProfile : ArduPilotProfile() {
    override val rotorcraft: Boolean get() = false
    override val bootMode: String get() = "MANUAL"

    // ArduPlane's ModeRTL (and the QuadPlane returns and landings) refuse arming in _pre_arm_checks (ArduPlane/mode.h).
    private val notArmable = setOf("RTL", "QRTL", "QLAND", "LOITER_ALT_QLAND")

    override fun behaviour(name: String): Behaviour? = when {
        name == "AUTO" -> Behaviour.AUTO
        name == "RTL" -> Behaviour.RTL
        name == "LOITER" -> Behaviour.HOLD
        name == "CIRCLE" -> Behaviour.CIRCLE
        name == "GUIDED" -> Behaviour.GUIDED
        name == "TAKEOFF" -> Behaviour.TAKEOFF
        name.startsWith("Q") || name == "LOITER_ALT_QLAND" -> null // not a QuadPlane
        else -> Behaviour.MANUAL
    }

    override fun armable(name: String, params: SimParameters): Boolean = name !in notArmable

    /** ArduPlane lands through its mission's landing sequence (DO_LAND_START): NAV_LAND is UNSUPPORTED. */
    override val landMode: String? get() = null
    override val landStartMode: String get() = "AUTO"

    /** ArduPlane checks the location first and then answers FAILED outside GUIDED (handle_command_int_do_reposition). */
    override val repositionOutsideGuidedAfterChecks: CommandResult get() = CommandResult.FAILED

    /** A destination outside the fence is refused before any mode change: DENIED. */
    override val repositionOutsideFence: CommandResult get() = CommandResult.DENIED

    /**
     * ArduPlane in GUIDED flies to [target] and circles it (GCS_MAVLINK_Plane::
     * handle_command_int_do_reposition): param4 NaN or 0 means clockwise, anything else
     * counter-clockwise; Plane::set_guided_WP also turns counter-clockwise when WP_LOITER_RAD is
     * negative. A param3 > 0 sets GUIDED's radius and takes the direction from param4 alone
     * (ModeGuided::set_radius_and_direction); the radius stays until the plane leaves GUIDED, and
     * none (≤ 1 m) means WP_LOITER_RAD (Plane::update_loiter). Farther than three radii it flies
     * the line from where it is (see Activity.GoTo).
     */
    override fun guidedGoTo(cmd: CommandRequest, target: Location, vehicle: FlightControl): Activity.GoTo {
        val counterClockwise = !(cmd.param4.isNaN() || cmd.param4 == 0f)
        val loiterRad = vehicle.params["WP_LOITER_RAD"]
        val clockwise = if (cmd.param3 > 0f) {
            vehicle.setGuidedRadius(cmd.param3.toDouble().coerceAtMost(UINT16_MAX))
            !counterClockwise
        } else {
            !(counterClockwise || loiterRad < 0)
        }
        val radius = vehicle.guidedRadius.takeIf { it > 1.0 } ?: kotlin.math.abs(loiterRad)
        return Activity.GoTo(target, null, radius, clockwise, from = vehicle.body.location)
    }

    private const val UINT16_MAX = 65535.0
    override val afterTakeoffMode: String get() = "LOITER"

    /**
     * ArduPlane notices within one loop that AUTO has no mission to run and switches to RTL
     * (ModeAuto::update, ArduPlane/mode_auto.cpp: "Aircraft in auto without a running mission").
     */
    override fun modeWhenMissionGone(current: String): String? = "RTL".takeIf { current == "AUTO" }

    /**
     * ArduPlane names the mode (AP_Arming_Plane::pre_arm_checks: "%s %s" of the mode's name and
     * "mode not armable"; ModeRTL::_pre_arm_checks refuses): "Arm: RTL mode not armable".
     */
    override fun modeNotArmableText(name: String): String = "Arm: $name mode not armable"

    /**
     * ArduPlane will not arm a mission holding DO_LAND_START while RTL_AUTOLAND is 0, its default
     * (AP_Arming_Plane::mission_checks).
     */
    override fun refusesLandStart(vehicle: ArmingView): Boolean = vehicle.params["RTL_AUTOLAND"].toInt() == 0 && vehicle.hasLandStart

    /**
     * ArduPlane's NAV_LAND never completes in AP_Landing::type_slope_verify_land: it flies the
     * glide slope from the previous waypoint (AP_Landing_Slope.cpp, see SlopeLanding).
     */
    override val landsOnGlideSlope: Boolean get() = true

    /** A mission that ends in the air ends in RTL (ArduPlane's exit_mission_callback). */
    override val missionEndMode: String get() = "RTL"

    /**
     * ArduPlane flies a zero altitude at the current one only when latitude and longitude are zero
     * too, a "loiter on the spot" (ArduPlane/commands.cpp, `Plane::set_next_WP`: "additionally
     * treat zero altitude as current altitude" inside the lat == 0 && lng == 0 branch); a located
     * item at 0 m is flown at 0 m.
     */
    override fun zeroAltitudeMeansCurrent(item: MissionItem): Boolean = item.x == 0 && item.y == 0

    override fun performance(params: SimParameters, overrides: SpeedOverrides): Performance = Performance(
        cruise = overrides.cruise ?: params["AIRSPEED_CRUISE"], climb = overrides.climb ?: params["TECS_CLMB_MAX"],
        descent = overrides.descent ?: params["TECS_SINK_MAX"], minAirspeed = params["AIRSPEED_MIN"], maxAirspeed = params["AIRSPEED_MAX"],
        bankLimit = params["ROLL_LIMIT_DEG"], loiterRadius = kotlin.math.abs(params["WP_LOITER_RAD"]),
    )

    /** WP_LOITER_RAD, negative for counter-clockwise. */
    override fun loiterCircle(params: SimParameters): Pair<Double, Boolean> = params["WP_LOITER_RAD"].let { kotlin.math.abs(it) to (it >= 0) }
    override fun defaultAcceptanceRadius(params: SimParameters): Double = params["WP_RADIUS"]
    override fun defaultTakeoffHeight(params: SimParameters): Double = params["TKOFF_ALT"]

    /** LAND_DISARMDELAY after a landing (0: never); never otherwise. */
    override fun autoDisarmDelay(params: SimParameters, afterLanding: Boolean): Double? =
        if (afterLanding) params["LAND_DISARMDELAY"].takeIf { it > 0 } else null

    override val autoDisarmText: String get() = "Disarming motors"

    /** RTL at ALT_HOLD_RTL (cm above home; -1: the current altitude), circling home at RTL_RADIUS (0: WP_LOITER_RAD). */
    override fun returnAltitude(params: SimParameters, homeAlt: Double, alt: Double): Triple<Double, Double, Boolean> {
        val (radius, cw) = loiterCircle(params)
        val rtlAlt = params["ALT_HOLD_RTL"].let { if (it < 0) alt else homeAlt + it / 100 }
        val r = params["RTL_RADIUS"].let { if (it == 0.0) radius to cw else kotlin.math.abs(it) to (it > 0) }
        return Triple(rtlAlt, r.first, r.second)
    }

    override fun parameters(systemId: Int): List<ParamDef> = ParamTables.arduPlane(systemId)

    /**
     * ArduPlane streams its groups at 1 Hz (libraries/GCS_MAVLink/GCS_MAVLink_Parameters.cpp, the
     * ArduPlane defaults): SYS_STATUS, MISSION_CURRENT, GPS_RAW_INT (EXT_STAT), GLOBAL_POSITION_INT
     * (POSITION), ATTITUDE (EXTRA1), VFR_HUD (EXTRA2); HOME_POSITION and EXTENDED_SYS_STATE only
     * when asked.
     */
    override val streamDefaults: Map<Int, Double> = mapOf(
        MessageIds.SYS_STATUS to 1.0,
        MessageIds.MISSION_CURRENT to 1.0,
        MessageIds.GPS_RAW_INT to 1.0,
        MessageIds.GLOBAL_POSITION_INT to 1.0,
        MessageIds.ATTITUDE to 1.0,
        MessageIds.VFR_HUD to 1.0,
    )
}
