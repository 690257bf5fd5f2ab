package pod.sim.autopilot.profile

import pod.mavlink.telemetry.Px4CustomMode
import pod.core.vehicle.Autopilot
import pod.mavlink.MessageIds
import pod.mavlink.command.CommandResult
import pod.mavlink.command.MavCommands
import pod.mavlink.mission.MissionItem
import pod.mavlink.vehicle.MissionServerFlavor
import pod.sim.autopilot.Behaviour
import pod.sim.autopilot.CommandReplies
import pod.sim.autopilot.CommandRequest
import pod.sim.autopilot.FlightControl
import pod.sim.autopilot.Geofence
import pod.sim.autopilot.Px4Geofence
import pod.sim.autopilot.OrbitCommand
import pod.sim.autopilot.SimParameters

/** What PX4 (1.16) does on either airframe: the PX4 family's facts. */
internal sealed class Px4Profile : AutopilotProfile() {
    override val autopilot: Autopilot get() = Autopilot.PX4
    override val missionServerFlavor: MissionServerFlavor get() = MissionServerFlavor.PX4
    override val bootMode: String get() = "AUTO.LOITER"

    override fun behaviour(name: String): Behaviour? = when (name) {
        "MANUAL", "STABILIZED", "ACRO", "RATTITUDE", "ALTCTL" -> Behaviour.MANUAL
        // POSCTL.ORBIT: OrbitCommand sets the circle; entered otherwise it holds here.
        "POSCTL", "OFFBOARD", "AUTO.LOITER", "AUTO.READY", "AUTO.FOLLOW_TARGET", "POSCTL.ORBIT" -> Behaviour.HOLD
        "AUTO.MISSION" -> Behaviour.AUTO
        "AUTO.RTL" -> Behaviour.RTL
        "AUTO.LAND", "AUTO.PRECLAND" -> Behaviour.LAND
        "AUTO.TAKEOFF" -> Behaviour.TAKEOFF
        else -> null
    }

    /** Orbit prevents arming too (ModeUtil/mode_requirements.cpp: mode_req_prevent_arming). */
    override fun armable(name: String, params: SimParameters): Boolean = name !in setOf("AUTO.RTL", "AUTO.LAND", "POSCTL.ORBIT")

    override val returnMode: String get() = "AUTO.RTL"
    override val guidedMode: String get() = HOLD
    override val landMode: String get() = "AUTO.LAND"
    override val landStartMode: String get() = "AUTO.MISSION"
    override val afterTakeoffMode: String get() = HOLD

    /** Commander answers a refused command TEMPORARILY_REJECTED. */
    override val refusal: CommandResult get() = CommandResult.TEMPORARILY_REJECTED

    /** PX4 keeps the text first: commander logs before it publishes the ack. */
    override val textBeforeAck: Boolean get() = true

    /** PX4 acknowledges the legacy SET_MODE message as DO_SET_MODE. */
    override val setModeMessageAck: Int get() = MavCommands.DO_SET_MODE

    /** DO_SET_MODE's param2 is the main mode, param3 the sub mode (packed as in px4_custom_mode.h). */
    override fun setModeCustomMode(param2: Float, param3: Float): Long = Px4CustomMode.pack(param2.toInt(), param3.toInt())

    override val setModeWithoutCustomFlag: CommandResult get() = CommandResult.TEMPORARILY_REJECTED

    /**
     * PX4 Commander, VEHICLE_CMD_DO_SET_MODE: a POSCTL sub mode other than SLOW selects plain
     * POSCTL (only DO_ORBIT enters the orbit); the bare AUTO main mode is not a mode.
     */
    override fun selectableMode(decoded: String): String? {
        val name = if (decoded == OrbitCommand.ORBIT) "POSCTL" else decoded
        return name.takeUnless { it.startsWith("MODE(") || it == "AUTO" }
    }

    override val unknownModeText: String get() = "Unsupported mode"
    override val noMissionText: String get() = "Mission start denied! No valid mission"

    /** OFFBOARD needs a stream of setpoints, which the simulator never gets. */
    override fun modeRefusalText(name: String): String? = "Offboard mode: no setpoints".takeIf { name == "OFFBOARD" }

    override val handlesOrbit: Boolean get() = true

    override fun takeoff(cmd: CommandRequest, vehicle: FlightControl, replies: CommandReplies): CommandResult = Px4Commands.takeoff(cmd, vehicle, replies)

    override fun missionStart(cmd: CommandRequest, vehicle: FlightControl, replies: CommandReplies): CommandResult = Px4Commands.missionStart(cmd, vehicle, replies)

    /** PX4 only acts on a DO_REPOSITION in Hold (or with the change-mode flag); elsewhere it acks and stays. */
    override val repositionIgnoredOutsideGuided: Boolean get() = true
    override val disarmInFlightText: String get() = "Disarming denied: not landed"

    /** PX4's arming checks in the order commander reports them, only the first; a further check is one more entry. */
    override fun armingRefusals(vehicle: ArmingView): List<String> = listOfNotNull(
        "Arming denied: no valid global position estimate".takeIf { !vehicle.positionReady },
        "Arming denied: low battery".takeIf { vehicle.charge < vehicle.params["BAT_LOW_THR"] },
        "Arming denied: mode not armable".takeIf { !armable(vehicle.modeName, vehicle.params) },
        "Arming denied: calibration in progress".takeIf { vehicle.calibrating },
    ).take(1)

    /** PX4 missions have no home item: AUTO flies from item 0. */
    override val firstMissionItem: Int get() = 0

    /** PX4's mission manager announces a new current item with MISSION_CURRENT. */
    override val announcesMissionCurrent: Boolean get() = true

    /** PX4 takes off by itself before the first item (ArduPilot needs a take-off item). */
    override val autoTakesOffByItself: Boolean get() = true

    /** A mission that ends in the air ends in Hold (navigator's mission end: AUTO.LOITER). */
    override val missionEndMode: String get() = HOLD

    /**
     * PX4 takes a zero altitude as given (src/modules/navigator/mission_block.cpp,
     * `MissionBlock::get_absolute_altitude_for_item` adds home to a relative altitude, whatever it
     * is), so a waypoint at 0 m above home is flown at ground level.
     */
    override fun zeroAltitudeMeansCurrent(item: MissionItem): Boolean = false

    /** PX4's geofence (navigator's geofence and commander's failsafe). */
    override fun fence(vehicle: FlightControl): Geofence = Px4Geofence(vehicle)

    override fun loiterCircle(params: SimParameters): Pair<Double, Boolean> = params["NAV_LOITER_RAD"] to true
    override fun defaultTakeoffHeight(params: SimParameters): Double = params["MIS_TAKEOFF_ALT"]

    /** COM_DISARM_LAND after a landing, else COM_DISARM_PRFLT (negative: never). */
    override fun autoDisarmDelay(params: SimParameters, afterLanding: Boolean): Double? =
        (if (afterLanding) params["COM_DISARM_LAND"] else params["COM_DISARM_PRFLT"]).takeIf { it >= 0 }

    override val autoDisarmText: String get() = "Disarmed by auto disarm"

    /** Returns at RTL_RETURN_ALT above home (a multicopter stays higher if it is), circling at NAV_LOITER_RAD. */
    override fun returnAltitude(params: SimParameters, homeAlt: Double, alt: Double): Triple<Double, Double, Boolean> {
        val (radius, cw) = loiterCircle(params)
        return Triple(maxOf(homeAlt + params["RTL_RETURN_ALT"], if (rotorcraft) alt else 0.0), radius, cw)
    }

    /** PX4 refuses values outside a parameter's range and stays silent on read-only writes. */
    override val refusesOutOfRange: Boolean get() = true

    /** PX4 sends integer parameters bytewise, the int32's bits inside the float field. */
    override val integersBytewise: Boolean get() = true

    /** COM_DISARM_PRFLT -1 keeps it armed on the ground. */
    override val keepArmedOnGround: Pair<String, Double> get() = "COM_DISARM_PRFLT" to -1.0

    /**
     * PX4's streams unasked (MAVLINK_MODE_NORMAL in src/modules/mavlink/mavlink_main.cpp,
     * Mavlink::configure_streams_to_default): SYS_STATUS, GPS_RAW_INT, EXTENDED_SYS_STATE,
     * MISSION_CURRENT 1 Hz; GLOBAL_POSITION_INT, ATTITUDE, VFR_HUD 2 Hz; HOME_POSITION 0.2 Hz;
     * DISTANCE_SENSOR 0.5 Hz, which carries something only when a distance sensor publishes
     * (streams/DISTANCE_SENSOR.hpp sends one message per updated distance_sensor topic).
     */
    override val streamDefaults: Map<Int, Double> get() = STREAM_DEFAULTS

    /** PX4 1.16.0. */
    override val version: Pair<Int, Int> get() = 1 to 16

    /** MAV_PROTOCOL_CAPABILITY_PARAM_ENCODE_BYTEWISE. */
    override val paramEncodingCapability: Int get() = 0x10

    /**
     * MavlinkStreamStatustext::send (src/modules/mavlink/streams/STATUSTEXT.hpp): every text takes
     * the next value of a uint16 counter that starts at 0 (`msg.id = _id++`), short ones too, so its
     * first text, chunked or not, has id 0; the chunks stop with the one that holds the end.
     */
    override fun statusTextChunks(text: String, ids: TextIds): List<TextChunk> {
        val id = ids.last
        ids.last = (ids.last + 1) and 0xFFFF
        val field = ArduPilotProfile.TEXT_FIELD
        val count = maxOf(1, (text.length + field - 1) / field)
        return (0 until count).map { i -> TextChunk(id, i, text.substring(i * field, minOf((i + 1) * field, text.length))) }
    }

    companion object {
        /** PX4's Hold mode. */
        const val HOLD = "AUTO.LOITER"

        /** See [streamDefaults]. */
        val STREAM_DEFAULTS: Map<Int, Double> = mapOf(
            MessageIds.SYS_STATUS to 1.0,
            MessageIds.GPS_RAW_INT to 1.0,
            MessageIds.ATTITUDE to 2.0,
            MessageIds.GLOBAL_POSITION_INT to 2.0,
            MessageIds.HOME_POSITION to 0.2,
            MessageIds.EXTENDED_SYS_STATE to 1.0,
            MessageIds.VFR_HUD to 2.0,
            MessageIds.MISSION_CURRENT to 1.0,
            MessageIds.DISTANCE_SENSOR to 0.5,
        )
    }
}
