package pod.mavlink.firmware

import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleIdentity
import pod.core.vehicle.VehicleType
import pod.mavlink.param.ParamEncoding
import pod.mavlink.plan.MissionFlavor
import pod.mavlink.telemetry.ModeRole

/**
 * What the ground side knows of how one firmware behaves, in one place: each fact is a named
 * member, so a new fact (or a new firmware) is one change here instead of one more
 * `autopilot == PX4` test wherever it is needed. The simulator's counterpart is
 * `pod.sim.autopilot.profile.AutopilotProfile`; the sources are in docs/real-autopilot-behaviour.md.
 *
 * Obtain one from what a vehicle announced with [of]. Defaults here are "no such quirk"; each
 * member overrides what its firmware does differently.
 */
public sealed class Firmware {
    /** How missions are written for this firmware (item 0, plane approach, PX4's refusals). */
    public abstract val missionFlavor: MissionFlavor

    /** True for fixed-wing airframes (FIXED_WING and VTOL), which cannot hover. */
    public abstract val fixedWing: Boolean

    /**
     * The name of the mode that plays [role], or null when there is none (an ArduPilot plane has no
     * LAND mode: it lands through its mission's landing sequence). [ModeRole.HOLD] keeps position
     * and altitude with nobody on the sticks, since a vehicle Pod flies may have no transmitter.
     */
    public abstract fun modeFor(role: ModeRole): String?

    /** Whether the vehicle arms in the mode called [mode]; Pod switches out of the others first. */
    public abstract fun armsIn(mode: String): Boolean

    /** How a take-off on command is made ([TakeOffWay]). */
    public abstract val takeOffWay: TakeOffWay

    /**
     * True when item 0 of the mission list is home and is not flown: ArduPilot keeps home there
     * (libraries/AP_Mission/AP_Mission.cpp); PX4 and generic autopilots store only the items flown.
     * Read from [missionFlavor], so that the two never disagree.
     */
    public val itemZeroIsHome: Boolean get() = missionFlavor.homeAtZero

    /**
     * True when a mission flown from the ground must begin with a take-off item: ArduCopter and
     * ArduPlane fly AUTO from the first item as it is, while PX4 takes off by itself
     * (docs/mavlink-missions.md).
     */
    public open val missionNeedsTakeOff: Boolean get() = false

    /**
     * The role of the mode to switch to before arming for a mission, or null to arm where it is
     * ([pod.mavlink.executor.MissionReplacement.armingMode] says why for each firmware).
     */
    public open val missionArmingRole: ModeRole? get() = null

    /** True when MISSION_CLEAR_ALL may be refused and the upload replaces the list anyway (ArduPilot: AP_Mission::clear while flying AUTO). */
    public open val mayRefuseMissionClear: Boolean get() = false

    /**
     * True when the vehicle keeps mission items in its own packed form, so what it sends back is
     * compared in that form (ArduPilot: libraries/AP_Mission/AP_Mission.cpp `mavlink_int_to_mission_cmd`).
     */
    public open val storesMissionPacked: Boolean get() = false

    /** True when the vehicle is known to serve a mission download in order, one request at a time (PX4). */
    public open val servesMissionInOrder: Boolean get() = false

    /**
     * True when MISSION_START arms the vehicle itself and takes the first item in param1 (PX4
     * Commander: VEHICLE_CMD_MISSION_START changes to AUTO_MISSION and calls arm()); ArduPilot
     * takes it disarmed and switches to AUTO on the ground, where a copter then will not arm.
     */
    public open val missionStartArms: Boolean get() = false

    /** True when DO_REPOSITION switches to the guided mode by itself (PX4); elsewhere Pod switches first. */
    public open val repositionSwitchesMode: Boolean get() = false

    /** True when DO_REPOSITION's param3 sets a plane's loiter radius around the target (ArduPlane's GUIDED). */
    public open val repositionTakesLoiterRadius: Boolean get() = false

    /** True when DO_ORBIT circles a point by itself (PX4); ArduCopter's circles are flown from the ground. */
    public open val orbitsOnCommand: Boolean get() = false

    /** True when a plane lands through the mission's landing sequence (DO_LAND_START), having no LAND mode (ArduPlane). */
    public open val landsThroughLandingSequence: Boolean get() = false

    /**
     * True when DO_PAUSE_CONTINUE pauses a flight in the guided mode too, not only a mission
     * (ArduCopter: GCS_MAVLINK_Copter::handle_command_pause_continue, ModeGuided::pause).
     */
    public open val pausesGuidedFlight: Boolean get() = false

    /** The modes a multirotor takes NAV_TAKEOFF in, for a hint when it refuses one elsewhere; null when no such rule is known. */
    public open val takeOffCommandModes: Set<String>? get() = null

    /**
     * True when every STATUSTEXT carries an id, single-chunk lines included, and the id counter
     * wraps at 65536 (PX4 `mavlink_log`); ArduPilot numbers only the chunks of a long line.
     */
    public open val numbersEveryStatusText: Boolean get() = false

    /** How integers are packed into PARAM_VALUE: by value on ArduPilot, bit for bit elsewhere. */
    public open val paramEncoding: ParamEncoding get() = ParamEncoding.BYTEWISE

    /** The parameter holding a plane's loiter radius, in metres (ArduPlane WP_LOITER_RAD, PX4 NAV_LOITER_RAD). */
    public open val loiterRadiusParam: String get() = "WP_LOITER_RAD"

    /** The parameter with a multirotor's default horizontal speed, in units of [hoverSpeedPerMetre] (ArduCopter WPNAV_SPEED in cm/s). */
    public open val hoverSpeedParam: String get() = "WPNAV_SPEED"

    /** How many units of [hoverSpeedParam] make one metre per second. */
    public open val hoverSpeedPerMetre: Double get() = 100.0

    /** The parameter with a plane's cruise airspeed in m/s (ArduPlane 4.5 and later: AIRSPEED_CRUISE). */
    public open val cruiseSpeedParam: String get() = "AIRSPEED_CRUISE"

    /** Finds a vehicle's firmware from what its heartbeat says. */
    public companion object {
        /** The firmware of a vehicle whose heartbeat said [autopilot] flying [type]. */
        public fun of(autopilot: Autopilot, type: VehicleType): Firmware {
            val plane = type == VehicleType.FIXED_WING || type == VehicleType.VTOL
            return when (autopilot) {
                Autopilot.ARDUPILOT -> if (plane) ArduPlane else ArduCopter
                Autopilot.PX4 -> if (plane) Px4FixedWing else Px4Multicopter
                Autopilot.GENERIC, Autopilot.OTHER -> GenericFirmware(plane)
            }
        }

        /** The firmware of [autopilot], for facts that do not depend on the airframe (its multicopter member). */
        public fun of(autopilot: Autopilot): Firmware = of(autopilot, VehicleType.OTHER)

        /** The firmware of the vehicle [identity] describes. */
        public fun of(identity: VehicleIdentity): Firmware = of(identity.autopilot, identity.type)
    }
}

/** How a vehicle takes off when told to. */
public enum class TakeOffWay {
    /** NAV_TAKEOFF in GUIDED, armed (ArduCopter: Mode::do_user_takeoff, has_user_takeoff in ArduCopter/mode.h). */
    COMMAND_IN_GUIDED,

    /** The TAKEOFF mode, climbing to TKOFF_ALT (ArduPlane). */
    TAKEOFF_MODE,

    /** NAV_TAKEOFF to an altitude above sea level in any mode, which switches to Takeoff (PX4 Commander). */
    COMMAND_ANYWHERE,
}
