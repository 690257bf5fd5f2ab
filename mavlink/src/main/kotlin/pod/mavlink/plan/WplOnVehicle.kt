package pod.mavlink.plan

import pod.core.units.Location
import pod.core.vehicle.Autopilot
import pod.mavlink.MavFrames
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType

/**
 * A QGC WPL 110 mission file as the list a vehicle stores, and back, the way QGroundControl and
 * Mission Planner treat line 0.
 *
 * The format follows ArduPilot: line 0 of a mission is home (ArduPilot keeps home in MISSION item 0
 * and writes its own over whatever is uploaded there). PX4 has no home item: QGC leaves the home
 * line out when it sends a mission to PX4 (`PX4FirmwarePlugin`'s `sendHomePositionToVehicle` is
 * false; `MissionManager::writeMissionItems`). Sent as it is, line 0 would become a real waypoint at
 * ground level that PX4 flies first (SITL, main of 2025-02: "mission started", the vehicle never
 * leaves the ground, "Disarmed by auto preflight disarming"). Fence and rally files have no home
 * line and go as they are.
 */
public object WplOnVehicle {
    /** The [type] list a vehicle of [autopilot] is sent for [fileItems] (a file's items, numbered from 0). */
    public fun toVehicle(fileItems: List<MissionItem>, type: MissionType, autopilot: Autopilot): List<MissionItem> {
        if (type != MissionType.MISSION || PlanOnVehicle.keepsHome(autopilot) || fileItems.isEmpty()) return fileItems
        return fileItems.drop(1).map { it.copy(seq = it.seq - 1) }
    }

    /**
     * The file's items for the [type] list [downloaded] from a vehicle of [autopilot]: on a vehicle
     * without a home item (PX4), the mission gets a line 0 at the vehicle's [home] (0, 0, 0 when it has
     * none), so that the file reads back as it was uploaded.
     */
    public fun toFile(downloaded: List<MissionItem>, type: MissionType, autopilot: Autopilot, home: Location?): List<MissionItem> {
        if (type != MissionType.MISSION || PlanOnVehicle.keepsHome(autopilot) || downloaded.isEmpty()) return downloaded
        val homeLine = MissionItem(
            seq = 0, frame = MavFrames.GLOBAL, command = NAV_WAYPOINT, current = true,
            x = home?.let { Math.round(it.latitude * 1e7).toInt() } ?: 0,
            y = home?.let { Math.round(it.longitude * 1e7).toInt() } ?: 0,
            z = home?.altitude?.meters?.toFloat() ?: 0f,
            missionType = MissionType.MISSION,
        )
        return listOf(homeLine) + downloaded.map { it.copy(seq = it.seq + 1, current = false) }
    }

    private const val NAV_WAYPOINT = 16
}
