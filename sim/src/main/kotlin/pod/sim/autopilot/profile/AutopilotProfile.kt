package pod.sim.autopilot.profile

import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.command.CommandResult
import pod.mavlink.mission.MissionItem
import pod.mavlink.vehicle.MissionServerFlavor
import pod.core.units.Location
import pod.sim.autopilot.Activity
import pod.sim.autopilot.Behaviour
import pod.sim.autopilot.CommandReplies
import pod.sim.autopilot.CommandRequest
import pod.sim.autopilot.FlightControl
import pod.sim.autopilot.Geofence
import pod.sim.autopilot.ParamDef
import pod.sim.autopilot.SimParameters
import pod.sim.autopilot.SpeedOverrides
import pod.sim.flight.Airframe
import pod.sim.flight.FixedWingAirframe
import pod.sim.flight.MultirotorAirframe
import pod.sim.flight.Performance

/**
 * Everything one firmware does that another does not, for the four firmwares the simulator plays:
 * [ArduCopterProfile], [ArduPlaneProfile], [Px4MulticopterProfile] and [Px4FixedWingProfile]. A
 * fact shared by a family lives in [ArduPilotProfile] or [Px4Profile]; a fact of one firmware in
 * its own object. The rest of the simulator asks the profile and never which autopilot it plays,
 * so a new firmware fact is one member here (with its source in the firmware's code beside it)
 * and a new firmware one more object.
 *
 * [rotorcraft] is the one member that is not a firmware fact: it picks the airframe's physics.
 */
internal sealed class AutopilotProfile {
    /** The autopilot family its HEARTBEAT names. */
    abstract val autopilot: Autopilot

    /** The airframe hovers (multirotor physics) rather than flying on wings: physics, not firmware. */
    abstract val rotorcraft: Boolean

    /** The physics of [rotorcraft]'s airframe. */
    val airframe: Airframe get() = if (rotorcraft) MultirotorAirframe else FixedWingAirframe

    /** The mission-protocol behaviour of the family's vehicle side (storage, request style). */
    abstract val missionServerFlavor: MissionServerFlavor

    /**
     * Whether the mission server normalises stored items as the family does for a fixed wing
     * (mavlink's MissionServer `fixedWing`): the firmware's plane build, whatever the airframe.
     */
    val missionServerFixedWing: Boolean get() = !rotorcraft

    // ---- Modes -------------------------------------------------------------------------------

    /** The mode it boots in. */
    abstract val bootMode: String

    /** What mode [name] makes the vehicle do with nobody on the sticks, or null when it cannot fly it. */
    abstract fun behaviour(name: String): Behaviour?

    /** Whether arming is allowed in mode [name] with the parameters as they are. */
    abstract fun armable(name: String, params: SimParameters): Boolean

    /** Whether mode [name] is refused until the estimator's position is good enough to navigate. */
    open fun needsPosition(name: String): Boolean = false

    /** The mode NAV_RETURN_TO_LAUNCH switches to. */
    abstract val returnMode: String

    /** The mode DO_REPOSITION flies in. */
    abstract val guidedMode: String

    /** The mode NAV_LAND switches to, or null when the firmware has none (the command is UNSUPPORTED). */
    abstract val landMode: String?

    /** The mode MAV_CMD_DO_LAND_START flies the landing sequence in. */
    abstract val landStartMode: String

    /** The mode a take-off mode hands over to at the take-off altitude (null: it holds in the same mode). */
    abstract val afterTakeoffMode: String?

    /** The deceleration, m/s², with which mode [name] stops a multirotor (null: its own acceleration limit). */
    open fun holdBraking(name: String): Double? = null

    /** The mode an AUTO with no mission left switches to, from mode [current], or null when it stays. */
    open fun modeWhenMissionGone(current: String): String? = null

    // ---- Commands ----------------------------------------------------------------------------

    /** What a refused command is answered with. */
    abstract val refusal: CommandResult

    /** Whether the STATUSTEXT explaining a command goes before its COMMAND_ACK rather than after it. */
    abstract val textBeforeAck: Boolean

    /** The command id a SET_MODE message is acknowledged with. */
    abstract val setModeMessageAck: Int

    /** The custom_mode a DO_SET_MODE with [param2] and [param3] selects. */
    abstract fun setModeCustomMode(param2: Float, param3: Float): Long

    /** The answer to a DO_SET_MODE without MAV_MODE_FLAG_CUSTOM_MODE_ENABLED. */
    abstract val setModeWithoutCustomFlag: CommandResult

    /** The mode a DO_SET_MODE for [decoded] selects, or null when the firmware refuses it. */
    open fun selectableMode(decoded: String): String? = decoded.takeUnless { it.startsWith("MODE(") }

    /** The line explaining a refused DO_SET_MODE for a mode it does not know, or null for none. */
    open val unknownModeText: String? = null

    /** The line refusing AUTO without a mission. */
    abstract val noMissionText: String

    /** The line refusing a switch to mode [name] for a reason of the mode's own, or null. */
    open fun modeRefusalText(name: String): String? = null

    /** Whether AUTO is refused while armed on the ground when the mission does not start with a take-off. */
    open val autoNeedsTakeoffItemOnGround: Boolean = false

    /** The mode NAV_LOITER_UNLIM switches to, or null when it is UNSUPPORTED. */
    open val loiterUnlimitedMode: String? = null

    /** Whether MAV_CMD_DO_ORBIT is handled. */
    open val handlesOrbit: Boolean = false

    /** Whether MAV_CMD_DO_PAUSE_CONTINUE is handled. */
    open val handlesPauseContinue: Boolean = false

    /** Whether a DO_CHANGE_SPEED without a positive speed is DENIED (rather than accepted unchanged). */
    open val changeSpeedNeedsSpeed: Boolean = false

    /** The line refusing a disarm in flight before its ack, or null when the refusal says nothing. */
    open val disarmInFlightText: String? = null

    /** NAV_TAKEOFF on [vehicle]; [replies] explain a refusal. */
    abstract fun takeoff(cmd: CommandRequest, vehicle: FlightControl, replies: CommandReplies): CommandResult

    /** MAV_CMD_MISSION_START on [vehicle]; [replies] explain a refusal. */
    abstract fun missionStart(cmd: CommandRequest, vehicle: FlightControl, replies: CommandReplies): CommandResult

    /** Whether DO_REPOSITION is taken only as COMMAND_INT (UNSUPPORTED as COMMAND_LONG). */
    open val repositionNeedsCommandInt: Boolean = false

    /** The answer to a DO_REPOSITION outside the guided mode without the change-mode flag, before the location is checked, or null. */
    open val repositionOutsideGuidedFirst: CommandResult? = null

    /** The answer to a DO_REPOSITION outside the guided mode without the change-mode flag, once the location passed, or null. */
    open val repositionOutsideGuidedAfterChecks: CommandResult? = null

    /** Whether a DO_REPOSITION outside the guided mode without the change-mode flag is accepted and ignored. */
    open val repositionIgnoredOutsideGuided: Boolean = false

    /** The answer to a DO_REPOSITION outside the fence, or null: accepted, switching mode, and said after the ack. */
    open val repositionOutsideFence: CommandResult? = null

    /**
     * What a DO_REPOSITION to [target] makes [vehicle] fly: by default the point, at param1 m/s
     * when positive, stopping there. ArduCopter does so whatever param3/param4 say: its handler
     * passes only the location to ModeGuided::set_destination (ArduCopter/GCS_Mavlink.cpp,
     * GCS_MAVLINK_Copter::handle_command_int_do_reposition).
     */
    open fun guidedGoTo(cmd: CommandRequest, target: Location, vehicle: FlightControl): Activity.GoTo =
        Activity.GoTo(target, cmd.param1.toDouble().takeIf { it > 0 })

    // ---- Arming ------------------------------------------------------------------------------

    /** Every line refusing an arm command now, as the firmware reports them (empty: it may arm). */
    abstract fun armingRefusals(vehicle: ArmingView): List<String>

    // ---- Missions ----------------------------------------------------------------------------

    /** The first item AUTO flies (1 where item 0 is home). */
    abstract val firstMissionItem: Int

    /** Whether MISSION_CLEAR_ALL is refused while armed and flying the mission in AUTO. */
    open val refusesClearWhileFlyingMission: Boolean = false

    /** Whether setting the current item while flying the mission restarts that item at once. */
    open val setCurrentRestartsItem: Boolean = false

    /** Whether a change of the current item is announced with MISSION_CURRENT unasked. */
    open val announcesMissionCurrent: Boolean = false

    /** Whether AUTO on the ground climbs by itself before an item that is not a take-off. */
    open val autoTakesOffByItself: Boolean = false

    /** Whether a final NAV_LAND with no take-off after it disarms at touchdown and rewinds the mission. */
    open val disarmsAfterFinalLanding: Boolean = false

    /** Whether NAV_LAND is flown as a glide slope from the previous waypoint. */
    open val landsOnGlideSlope: Boolean = false

    /** Whether NAV_LOITER_TIME flies the loiter-radius parameter rather than its param3's radius. */
    open val loiterTimeUsesLoiterRadius: Boolean = false

    /** The mode the vehicle switches to when a mission ends in the air, or null when it stays in AUTO. */
    open val missionEndMode: String? = null

    /** The fence it enforces on [vehicle]. */
    abstract fun fence(vehicle: FlightControl): Geofence

    /** Whether [item], whose altitude is 0, is flown at the current altitude rather than at 0. */
    open fun zeroAltitudeMeansCurrent(item: MissionItem): Boolean = false

    // ---- Flight ------------------------------------------------------------------------------

    /** Speeds, rates and radii from the parameters, with DO_CHANGE_SPEED's [overrides]. */
    abstract fun performance(params: SimParameters, overrides: SpeedOverrides): Performance

    /** A plane's loiter radius (positive, m) and direction (true: clockwise); (0, true) for a multirotor. */
    abstract fun loiterCircle(params: SimParameters): Pair<Double, Boolean>

    /** The waypoint acceptance radius, m, when an item asks for none. */
    abstract fun defaultAcceptanceRadius(params: SimParameters): Double

    /** The take-off height above home when a take-off gives none, m. */
    abstract fun defaultTakeoffHeight(params: SimParameters): Double

    /** Seconds on the ground before an armed vehicle disarms itself (after a landing or not), or null: never. */
    abstract fun autoDisarmDelay(params: SimParameters, afterLanding: Boolean): Double?

    /** The line an automatic disarm says. */
    abstract val autoDisarmText: String

    /** The return to launch from [alt] (AMSL), home at [homeAlt]: (return altitude AMSL, radius, clockwise). */
    abstract fun returnAltitude(params: SimParameters, homeAlt: Double, alt: Double): Triple<Double, Double, Boolean>

    /** The descent with the throttle stick at minimum in a stick-climb-rate mode, m/s. */
    open fun pilotDescentRate(params: SimParameters): Double = error("$this has no stick climb-rate mode")

    /** Whether stick-climb-rate mode [name] holds its horizontal position while it descends (rather than stopping wherever it does). */
    open fun stickModeHoldsPosition(name: String): Boolean = true

    /** The circle CIRCLE mode flies around the point ahead: radius m and direction. */
    open fun circleMode(params: SimParameters): Pair<Double, Boolean> = error("$this has no circle mode")

    // ---- Parameters --------------------------------------------------------------------------

    /** The parameter table, with [systemId] as the system-id parameter. */
    abstract fun parameters(systemId: Int): List<ParamDef>

    /** Whether a write outside a parameter's documented range is refused. */
    open val refusesOutOfRange: Boolean = false

    /** Whether integer parameters travel bytewise (the int32's bits in the float) rather than C-cast. */
    open val integersBytewise: Boolean = false

    /** Whether a PARAM_SET of NaN or infinity is dropped without an answer. */
    open val dropsNonFiniteWrites: Boolean = false

    /** The line answering a write to read-only parameter [id], or null for none. */
    open fun readOnlyWriteText(id: String): String? = null

    /** The parameter and value that keep a vehicle armed on the ground armed, or null when none is needed. */
    open val keepArmedOnGround: Pair<String, Double>? = null

    // ---- Messages ----------------------------------------------------------------------------

    /** Message id → rate in Hz of what it streams before anyone asks (HEARTBEAT aside). */
    abstract val streamDefaults: Map<Int, Double>

    /** The firmware version it claims (major, minor). */
    abstract val version: Pair<Int, Int>

    /** The MAV_PROTOCOL_CAPABILITY bit saying how it packs integer parameters. */
    abstract val paramEncodingCapability: Int

    /** The chunks of STATUSTEXT [text] as (id, chunk_seq, part), taking ids from [ids]. */
    abstract fun statusTextChunks(text: String, ids: TextIds): List<TextChunk>

    /** Whether a photo is reported with ArduPilot's CAMERA_FEEDBACK rather than CAMERA_IMAGE_CAPTURED. */
    open val reportsCameraFeedback: Boolean = false

    companion object {
        /**
         * The profile of [autopilot] flying [type]: PX4 or ArduPilot (any other autopilot plays
         * ArduPilot), multirotor or plane. [VehicleType.OTHER] flies as a multirotor, as the
         * simulator's airframe choice always did.
         */
        fun of(autopilot: Autopilot, type: VehicleType): AutopilotProfile {
            val rotorcraft = type.isMultirotor || type == VehicleType.OTHER
            return when (autopilot) {
                Autopilot.PX4 -> if (rotorcraft) Px4MulticopterProfile else Px4FixedWingProfile
                else -> if (rotorcraft) ArduCopterProfile else ArduPlaneProfile
            }
        }
    }
}

/** One STATUSTEXT chunk: its [id], [seq] (chunk_seq) and [text]. */
internal data class TextChunk(val id: Int, val seq: Int, val text: String)

/** The STATUSTEXT id counter of one vehicle. */
internal class TextIds {
    /** The last id handed out (its meaning is the profile's). */
    var last: Int = 0
}
