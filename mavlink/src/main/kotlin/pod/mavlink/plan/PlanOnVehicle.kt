package pod.mavlink.plan

import pod.core.vehicle.Autopilot
import pod.mavlink.MavFrames
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
     * The plan of the [mission], [fence] and [rally] lists downloaded from a vehicle of [autopilot]: on
     * ArduPilot, item 0 becomes the planned home (AMSL) and the rest the mission from seq 0.
     *
     * @throws PlanListException when the fence or rally list does not describe a fence or rally points.
     */
    public fun plan(mission: List<MissionItem>, fence: List<MissionItem>, rally: List<MissionItem>, autopilot: Autopilot): QgcPlan {
        val home = mission.firstOrNull()?.takeIf { keepsHome(autopilot) }
        return QgcPlan(
            mission = if (home == null) mission else mission.drop(1).map { it.copy(seq = it.seq - 1) },
            geoFence = PlanLists.fence(fence),
            rallyPoints = PlanLists.rallyPoints(rally),
            plannedHome = home?.let { PlanPosition(it.latitude, it.longitude, it.z.toDouble()) },
        )
    }

    internal fun keepsHome(autopilot: Autopilot) = autopilot == Autopilot.ARDUPILOT

    private const val NAV_WAYPOINT = 16
}
