package pod.sim.autopilot.profile

import pod.core.vehicle.Autopilot
import pod.mavlink.MessageIds
import pod.mavlink.command.CommandResult
import pod.mavlink.vehicle.MissionServerFlavor
import pod.sim.autopilot.CommandReplies
import pod.sim.autopilot.CommandRequest
import pod.sim.autopilot.FlightControl
import pod.sim.autopilot.ArduPilotFence
import pod.sim.autopilot.Geofence
import pod.sim.autopilot.SimParameters
import pod.sim.autopilot.packVoltage

/** What ArduCopter and ArduPlane (4.7) share: the ArduPilot family's facts. */
internal sealed class ArduPilotProfile : AutopilotProfile() {
    override val autopilot: Autopilot get() = Autopilot.ARDUPILOT
    override val missionServerFlavor: MissionServerFlavor get() = MissionServerFlavor.ARDUPILOT
    override val returnMode: String get() = "RTL"
    override val guidedMode: String get() = "GUIDED"

    /** A refused command is FAILED (GCS_MAVLINK::handle_command_long answers MAV_RESULT_FAILED). */
    override val refusal: CommandResult get() = CommandResult.FAILED

    /**
     * ArduPilot sends the COMMAND_ACK first and the text after it: GCS_Common.cpp,
     * GCS_MAVLINK::handle_command_long sends the ack as soon as the handler returns, while
     * GCS::send_textv only queues the STATUSTEXT for GCS_MAVLINK::service_statustext to send on
     * the next update_send pass.
     */
    override val textBeforeAck: Boolean get() = false

    /** ArduPilot acknowledges the legacy SET_MODE message as "command 11" (the message id). */
    override val setModeMessageAck: Int get() = MessageIds.SET_MODE

    /** DO_SET_MODE's param2 is the custom_mode number itself. */
    override fun setModeCustomMode(param2: Float, param3: Float): Long = param2.toLong()

    override val setModeWithoutCustomFlag: CommandResult get() = CommandResult.UNSUPPORTED
    override val noMissionText: String get() = "Mode change to AUTO failed: no mission"

    /** The modes NAV_TAKEOFF takes off in, staying in them; null: it switches to TAKEOFF (a plane). */
    protected open val takeoffModes: Set<String>? = null

    override fun takeoff(cmd: CommandRequest, vehicle: FlightControl, replies: CommandReplies): CommandResult = arduTakeoff(cmd, vehicle, takeoffModes)

    override fun missionStart(cmd: CommandRequest, vehicle: FlightControl, replies: CommandReplies): CommandResult = arduMissionStart(cmd, replies)

    /** ArduPilot takes DO_REPOSITION only as COMMAND_INT (handle_command_int_do_reposition). */
    override val repositionNeedsCommandInt: Boolean get() = true

    /** DO_CHANGE_SPEED with no positive speed is DENIED. */
    override val changeSpeedNeedsSpeed: Boolean get() = true

    /**
     * ArduPilot runs all its checks on an arm command and reports each failure
     * (AP_Arming::pre_arm_checks and AP_Arming_Copter::run_pre_arm_checks chain them with `&`);
     * a further check is one more entry. The first two clear by waiting after boot, as on SITL
     * (texts as ArduPilot 4.7 SITL sent them): the inertial sensors' consistency
     * (AP_Arming::ins_checks, ins_accels_consistent) and home, which exists only once the EKF has
     * an origin (AP_Arming::gps_checks asks AP_AHRS::home_is_set: "AHRS: waiting for home"). An
     * arm command's failures start "Arm: " (AP_Arming::check_failed while arming).
     */
    override fun armingRefusals(vehicle: ArmingView): List<String> {
        val checksEnabled = vehicle.params["ARMING_CHECK"].toInt() != 0
        return listOfNotNull(
            "Arm: Accels inconsistent".takeIf { !vehicle.sensorsReady },
            "Arm: AHRS: waiting for home".takeIf { !vehicle.positionReady },
            "PreArm: Battery 1 below minimum arming voltage".takeIf { checksEnabled && packVoltage(vehicle.charge) < vehicle.params["BATT_ARM_VOLT"] },
            modeNotArmableText(vehicle.modeName).takeIf { !armable(vehicle.modeName, vehicle.params) },
            "Arm: DO_LAND_START set and RTL_AUTOLAND disabled".takeIf { checksEnabled && refusesLandStart(vehicle) },
            "PreArm: Calibration in progress".takeIf { vehicle.calibrating },
            vehicle.fenceArmingProblem?.let { "Arm: $it" },
        )
    }

    /** The line refusing to arm in mode [name]. */
    protected abstract fun modeNotArmableText(name: String): String

    /** Whether the mission's DO_LAND_START refuses arming with the parameters as they are. */
    protected open fun refusesLandStart(vehicle: ArmingView): Boolean = false

    /** ArduPilot's fence (AC_Fence), with Copter's or Plane's reactions. */
    override fun fence(vehicle: FlightControl): Geofence = ArduPilotFence(vehicle, copter = rotorcraft)

    /** Item 0 of a MISSION is home and is not flown. */
    override val firstMissionItem: Int get() = 1

    /**
     * ArduPilot will not clear a mission it is flying: AP_Mission::clear refuses while armed and
     * MISSION_RUNNING (in AUTO), and MissionItemProtocol::handle_mission_clear_all answers ERROR.
     */
    override val refusesClearWhileFlyingMission: Boolean get() = true

    /**
     * MISSION_SET_CURRENT (or DO_SET_MISSION_CURRENT) while flying the mission restarts the item
     * named, even the one it is flying: AP_Mission::set_current_cmd stops the current nav command
     * and advance_current_nav_cmd reads the item from storage again, at once
     * (libraries/AP_Mission/AP_Mission.cpp); AP_Mission::replace_cmd says a rewritten active item
     * has "no effect until the command is restarted".
     */
    override val setCurrentRestartsItem: Boolean get() = true

    /**
     * ArduPilot keeps no radius for NAV_LOITER_TIME, only the direction in param3's sign
     * (AP_Mission::mavlink_int_to_mission_cmd): the loiter radius parameter applies.
     */
    override val loiterTimeUsesLoiterRadius: Boolean get() = true

    /** ArduPilot drops a NaN or infinite PARAM_SET without a word (GCS_Param.cpp, handle_param_set). */
    override val dropsNonFiniteWrites: Boolean get() = true

    override fun readOnlyWriteText(id: String): String = "Param write denied ($id)"

    /** ArduPilot 4.7.0. */
    override val version: Pair<Int, Int> get() = 4 to 7

    /** MAV_PROTOCOL_CAPABILITY_PARAM_ENCODE_C_CAST. */
    override val paramEncodingCapability: Int get() = 0x20000

    /**
     * GCS::send_textv (libraries/GCS_MAVLink/GCS_Common.cpp): one message with id 0 when the text
     * fits, else chunks with one new non-zero id and chunk_seq 0, 1, …, the last one shorter
     * (empty when the text fills its chunks exactly).
     */
    override fun statusTextChunks(text: String, ids: TextIds): List<TextChunk> {
        if (text.length <= TEXT_FIELD) return listOf(TextChunk(0, 0, text))
        ids.last = if (ids.last >= 0xFFFF) 1 else ids.last + 1
        val parts = (0..text.length / TEXT_FIELD).map { i -> text.substring(minOf(i * TEXT_FIELD, text.length), minOf((i + 1) * TEXT_FIELD, text.length)) }
        return parts.mapIndexed { i, part -> TextChunk(ids.last, i, part) }
    }

    /**
     * ArduPilot 4.7's own camera backends send CAMERA_FEEDBACK (180) and no CAMERA_IMAGE_CAPTURED:
     * AP_Camera_Backend::take_picture → log_picture → prep_mavlink_msg_camera_feedback
     * (libraries/AP_Camera/AP_Camera_Backend.cpp).
     */
    override val reportsCameraFeedback: Boolean get() = true

    /** Reads AUTO_OPTIONS where the firmware has it (0 otherwise). */
    protected fun autoOptions(params: SimParameters): Int = params.valueOf("AUTO_OPTIONS")?.toInt() ?: 0

    companion object {
        /** Characters in STATUSTEXT's text field. */
        const val TEXT_FIELD = 50
    }
}
