package pod.mavlink.action

import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.CommandResult
import pod.mavlink.command.MavCommands.DO_PAUSE_CONTINUE
import pod.mavlink.command.MavCommands.MISSION_START
import pod.mavlink.command.VehicleCommand
import pod.mavlink.telemetry.ModeRole

/**
 * Flying the mission on board ([VehicleActions.startMission], [VehicleActions.pauseMission],
 * [VehicleActions.continueMission]). It remembers how the last pause was made, so that the resume
 * undoes that and nothing else.
 */
internal class MissionActions(
    private val vehicle: MavlinkVehicle,
    private val actions: VehicleActions,
    private val modes: ModeSwitch,
    private val guided: GuidedFlight,
    private val waits: StateWaits,
) {
    /** True: paused with DO_PAUSE_CONTINUE; false: by the hold mode; null: not by this process. */
    @Volatile private var pausedByCommand: Boolean? = null

    /** Pauses the mission where the vehicle is, with DO_PAUSE_CONTINUE or, where unsupported, the hold mode. */
    suspend fun pause() {
        if (!vehicle.telemetry.armed.value) throw NothingInFlight(vehicle.systemId, "pause")
        try {
            vehicle.commands.send(VehicleCommand(DO_PAUSE_CONTINUE, param1 = 0f))
            pausedByCommand = true
        } catch (e: CommandRejected) {
            when {
                e.result == CommandResult.UNSUPPORTED -> {
                    guided.hold()
                    pausedByCommand = false
                }
                // ArduCopter fails a pause when already paused: after a lost ack, the first send did it.
                e.result == CommandResult.FAILED && e.attempts > 1 -> pausedByCommand = true
                else -> throw e
            }
        }
    }

    /** Resumes what [pause] paused, by this process or another. */
    suspend fun resume() {
        vehicle.mission.requireWhole("resume the mission")
        if (!vehicle.telemetry.armed.value) throw NothingInFlight(vehicle.systemId, "resume")
        val mission = vehicle.modeFor(ModeRole.MISSION)
        val mode = vehicle.telemetry.mode.value?.name
        val pausedInMode = mode == mission ||
            (vehicle.firmware().pausesGuidedFlight && vehicle.identity.value.type.isMultirotor && mode == vehicle.modeFor(ModeRole.GUIDED))
        if (pausedByCommand == true || (pausedByCommand == null && pausedInMode)) {
            vehicle.commands.send(VehicleCommand(DO_PAUSE_CONTINUE, param1 = 1f))
        } else {
            modes.setMode(mission)
        }
        pausedByCommand = null
    }

    /** Starts the uploaded mission at item [first] (null: where it stands), arming first with [arm]. */
    suspend fun start(first: Int?, arm: Boolean) {
        vehicle.mission.requireWhole("start the mission")
        val px4 = vehicle.firmware().missionStartArms
        // ArduCopter and ArduPlane take MISSION_START disarmed and switch to AUTO on the ground
        // (GCS_MAVLINK_Copter::handle_MAV_CMD_MISSION_START, ArduPlane's GCS_MAVLINK_Plane: set_mode
        // AUTO only), where the copter then refuses to arm ("Mode not armable"); PX4 arms itself
        // (Commander: VEHICLE_CMD_MISSION_START changes to AUTO_MISSION and calls arm()).
        if (!px4 && !arm) waits.requireArmed("start the mission")
        if (first != null || arm) {
            // ArduPilot ignores MISSION_SET_CURRENT beyond its mission without a word
            // (GCS_MAVLINK::handle_mission_set_current answers only when set_current_cmd succeeds),
            // PX4 denies MISSION_START beyond seq_total: check against what the vehicle holds.
            val count = vehicle.mission.download().size
            // ArduPilot's item 0 is home: a mission to fly has more (ModeAuto::init: num_commands() > 1).
            // (A generic autopilot is counted the ArduPilot way here, as before firmware profiles.)
            val empty = count <= (if (px4) 0 else 1)
            if (first != null && first >= count) throw NoSuchMissionItem(vehicle.systemId, if (count == 0) null else first, count)
            if (empty) throw NoSuchMissionItem(vehicle.systemId, null, count)
        }
        if (arm) actions.armForFlight()
        if (first != null && !px4) vehicle.mission.setCurrent(first)
        vehicle.commands.send(VehicleCommand(MISSION_START, param1 = if (px4 && first != null) first.toFloat() else 0f))
        waits.confirmMode("start mission", ModeRole.MISSION)
    }
}
