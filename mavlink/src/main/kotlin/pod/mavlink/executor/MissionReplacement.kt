package pod.mavlink.executor

import pod.core.vehicle.VehicleIdentity
import pod.mavlink.MavlinkVehicle
import pod.mavlink.firmware.Firmware
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionRejected
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.telemetry.ModeRole

/**
 * Puts a new mission on a vehicle that may still be flying, or sitting armed in AUTO, with the last.
 *
 * ArduPilot refuses MISSION_CLEAR_ALL while it runs a mission armed in AUTO (AP_Mission::clear;
 * MissionItemProtocol::handle_mission_clear_all answers MAV_MISSION_ERROR). So a vehicle flying its
 * mission first holds, in the autopilot's hold mode, which keeps its altitude, and the mission is
 * no longer running. One still armed in AUTO on the ground (an ArduPlane after its landing: a
 * NAV_LAND never completes, AP_Landing::type_slope_verify_land) may still refuse the clear: the
 * upload replaces the list anyway, since ArduPilot truncates it to a MISSION_COUNT's size and
 * writes every item (MissionItemProtocol::handle_mission_count).
 */
internal object MissionReplacement {
    suspend fun replace(vehicle: MavlinkVehicle, items: List<MissionItem>, airborne: Boolean) {
        val identity = vehicle.identity.value
        if (airborne && vehicle.telemetry.mode.value?.name == FlightModes.forRole(identity.autopilot, identity.type, ModeRole.MISSION)) {
            vehicle.action.hold()
        }
        try {
            vehicle.mission.clear()
        } catch (e: MissionRejected) {
            if (!Firmware.of(identity).mayRefuseMissionClear) throw e
        }
        vehicle.mission.upload(items)
    }

    /**
     * The mode to switch to before arming, or null to arm in the current one:
     * - ArduCopter arms in GUIDED (AUTO then flies the take-off item);
     * - ArduPlane in its hold mode, always: a plane whose mission was cleared in AUTO switches to RTL
     *   on its next loop (ModeAuto::update, "Aircraft in auto without a running mission"), which the
     *   last heartbeat may not show yet, and ModeRTL refuses arming (ModeRTL::_pre_arm_checks,
     *   "Arm: RTL mode not armable"); the hold mode arms and keeps the throttle idle on the ground;
     * - PX4 stays where it is (null): [pod.mavlink.action.VehicleActions.armForFlight] leaves the
     *   modes it will not arm in (return, land, orbit) for its hold mode, as for any arming.
     */
    fun armingMode(identity: VehicleIdentity): String? {
        val firmware = Firmware.of(identity)
        return firmware.missionArmingRole?.let(firmware::modeFor)
    }
}
