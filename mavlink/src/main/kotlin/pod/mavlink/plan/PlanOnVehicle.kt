package pod.mavlink.plan

import pod.core.units.Location
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.MavlinkEnums
import pod.mavlink.MavFrames
import pod.mavlink.firmware.Firmware
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType

/**
 * A [QgcPlan] as the three lists a vehicle stores, and back, the way QGroundControl sends and reads them.
 *
 * A .plan file's mission holds no home item; ArduPilot keeps its home in MISSION item 0. So for ArduPilot
 * the planned home goes first and the plan's items follow from seq 1, and a downloaded item 0 is read back
 * as the planned home (QGC's `APMFirmwarePlugin::sendHomePositionToVehicle` is true; `MissionManager::
 * writeMissionItems` sends its home item as seq 0). PX4 and other autopilots take the items from seq 0
 * (the base `FirmwarePlugin` and `PX4FirmwarePlugin` say false). ArduPilot overwrites item 0 with its own
 * home, so what comes back there is where the vehicle's home is, not the planned one.
 */
public object PlanOnVehicle {
    /** The MISSION, FENCE and RALLY lists to upload [plan] to a vehicle of [autopilot], in that order. */
    public fun lists(plan: QgcPlan, autopilot: Autopilot): List<Pair<MissionType, List<MissionItem>>> = listOf(
        MissionType.MISSION to missionItems(plan, autopilot),
        MissionType.FENCE to PlanLists.fenceItems(plan.geoFence),
        MissionType.RALLY to PlanLists.rallyItems(plan.rallyPoints),
    )

    /** [plan]'s mission as a vehicle of [autopilot] stores it: after a home item on ArduPilot (see [PlanOnVehicle]). */
    public fun missionItems(plan: QgcPlan, autopilot: Autopilot): List<MissionItem> {
        if (!keepsHome(autopilot)) return plan.mission
        // With no planned home, a placeholder: ArduPilot writes its own home over item 0 in any case.
        val home = plan.plannedHome
        val homeItem = MissionItem(
            seq = 0, frame = MavFrames.GLOBAL, command = NAV_WAYPOINT,
            x = home?.let { Math.round(it.latitude * 1e7).toInt() } ?: 0,
            y = home?.let { Math.round(it.longitude * 1e7).toInt() } ?: 0,
            z = home?.altitude?.toFloat() ?: 0f,
            missionType = MissionType.MISSION,
        )
        return listOf(homeItem) + plan.mission.map { it.copy(seq = it.seq + 1) }
    }

    /**
     * The plan of the [mission], [fence] and [rally] lists downloaded from a vehicle of [autopilot] flying
     * [type] (the file's firmwareType and vehicleType; null: unknown, written 0): on ArduPilot, item 0 becomes
     * the planned home (AMSL) and the rest the mission from seq 0. Where item 0 does not hold a home (at
     * 0°, 0°: ArduPilot has none yet) or the autopilot keeps none in its mission (PX4), the planned home is
     * [home] (the vehicle's HOME_POSITION, AMSL), or none when that is unknown too. A yaw ArduPilot does
     * not store comes back 0 and is written as unknown (NaN, QGC's null), not as north.
     *
     * @throws PlanListException when the fence or rally list does not describe a fence or rally points.
     */
    public fun plan(
        mission: List<MissionItem>,
        fence: List<MissionItem>,
        rally: List<MissionItem>,
        autopilot: Autopilot,
        type: VehicleType? = null,
        home: Location? = null,
    ): QgcPlan {
        val homeItem = mission.firstOrNull()?.takeIf { keepsHome(autopilot) }
        val items = if (homeItem == null) mission else mission.drop(1).map { it.copy(seq = it.seq - 1) }
        return QgcPlan(
            mission = if (keepsHome(autopilot)) items.map(::unknownYaw) else items,
            geoFence = PlanLists.fence(fence),
            rallyPoints = PlanLists.rallyPoints(rally),
            plannedHome = homeItem?.takeIf { it.x != 0 || it.y != 0 }?.let { PlanPosition(it.latitude, it.longitude, it.z.toDouble()) }
                ?: home?.let { PlanPosition(it.latitude, it.longitude, it.altitude.meters) },
            firmwareType = MavlinkEnums.mavAutopilot(autopilot),
            vehicleType = type?.let(MavlinkEnums::mavType) ?: 0,
        )
    }

    /**
     * ArduPilot keeps no yaw for these commands (libraries/AP_Mission/AP_Mission.cpp,
     * `mavlink_int_to_mission_cmd` stores only p1 for them; `mission_cmd_to_mavlink_int` sends param4 0
     * back): a 0 there says nothing about the heading the plan asked for.
     */
    private fun unknownYaw(item: MissionItem): MissionItem =
        if (item.command in YAW_NOT_KEPT && item.param4 == 0f) item.copy(param4 = Float.NaN) else item

    internal fun keepsHome(autopilot: Autopilot) = Firmware.of(autopilot).itemZeroIsHome

    /** NAV_WAYPOINT, NAV_TAKEOFF, NAV_VTOL_TAKEOFF: the commands whose yaw may be sent NaN (`sanity_check_params`). */
    private val YAW_NOT_KEPT = setOf(16, 22, 84)

    private const val NAV_WAYPOINT = 16
}
