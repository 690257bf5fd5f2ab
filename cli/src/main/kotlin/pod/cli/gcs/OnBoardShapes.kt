package pod.cli.gcs

import pod.cli.json.OnBoard
import pod.cli.json.OnBoardCircle
import pod.cli.json.OnBoardItem
import pod.cli.json.OnBoardPolygon
import pod.cli.json.OnBoardRally
import pod.mavlink.mission.MissionItem
import pod.mavlink.plan.QgcPlan

/** A vehicle's downloaded lists as the map draws them ([OnBoard]). */
internal object OnBoardShapes {
    /**
     * [plan] (the lists of vehicle [sysid] as a plan: home taken out of an ArduPilot mission) with
     * [missionList], the mission as the vehicle numbers it, for each item's seq there.
     */
    fun of(sysid: Int, plan: QgcPlan, missionList: List<MissionItem>): OnBoard {
        // ArduPilot's item 0 is home: the plan's items are the vehicle's from seq 1.
        val offset = missionList.size - plan.mission.size
        val items = plan.mission.mapIndexedNotNull { index, item ->
            if (!item.isGlobal || (item.x == 0 && item.y == 0)) return@mapIndexedNotNull null
            OnBoardItem(
                seq = item.seq + offset, n = index + 1, command = item.command,
                lat = item.latitude, lon = item.longitude, alt = item.z.toDouble(), nav = item.command in NAV_COMMANDS,
            )
        }
        val fence = plan.geoFence
        return OnBoard(
            sysid = sysid,
            mission = items,
            polygons = fence.polygons.map { p -> OnBoardPolygon(p.inclusion, p.vertices.map { listOf(it.latitude, it.longitude) }) },
            circles = fence.circles.map { c -> OnBoardCircle(c.inclusion, c.center.latitude, c.center.longitude, c.radiusMetres) },
            rally = plan.rallyPoints.map { OnBoardRally(it.latitude, it.longitude, it.altitude) },
            home = plan.plannedHome?.let { listOf(it.latitude, it.longitude) },
            missionItems = plan.mission.size,
        )
    }

    /**
     * MAV_CMD_NAV_WAYPOINT (16) up to MAV_CMD_NAV_LAST (95), MAVLink's range of commands that move
     * the vehicle (common.xml); DO_ and CONDITION_ commands with a place (a region of interest) are
     * drawn but not joined into the path.
     */
    private val NAV_COMMANDS = 16..95
}
