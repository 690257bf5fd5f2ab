package pod.cli.gcs

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import pod.mavlink.mission.MissionType

// The plans panel's requests: a file dropped on the page goes to a vehicle; what a vehicle holds
// comes back to the map. Downloading the plan as a file is an HTTP route (PlanRoutes).

/**
 * `{"op":"plan_upload","id":7,"sysid":1,"name":"survey.plan","text":"…"}`: uploads the file's
 * lists to vehicle [sysid] (a .plan: mission, fence and rally; a WPL file: the [list] it names,
 * the mission by default). Answered once the vehicle holds them, with what went; progress comes
 * as `plan_progress` events meanwhile, and the map's `on_board` lists are read back after.
 */
@Serializable @SerialName("plan_upload")
public data class PlanUpload(
    override val id: Long,
    val sysid: Int,
    val name: String,
    val text: String,
    val list: String = "mission",
) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String {
        val type = MissionType.entries.firstOrNull { it.name.equals(list, ignoreCase = true) }
            ?: throw GcsRequestException("list must be mission, fence or rally, was '$list'")
        val file = PlanFile.read(name, text, type)
        return fleet.service(PlanDesk::class) { PlanDesk(it) }.upload(sysid, file)
    }
}

/**
 * `{"op":"plan_on_board","id":8,"sysid":1}`: downloads vehicle [sysid]'s mission, fence and rally
 * lists for the map (an `on_board` event to every page); answered with how many items each holds.
 */
@Serializable @SerialName("plan_on_board")
public data class PlanOnBoard(override val id: Long, val sysid: Int) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String {
        val plan = fleet.service(PlanDesk::class) { PlanDesk(it) }.show(sysid)
        val fence = plan.geoFence.polygons.sumOf { it.vertices.size } + plan.geoFence.circles.size
        return "vehicle $sysid holds ${plan.mission.size} mission items, $fence fence items and ${plan.rallyPoints.size} rally points"
    }
}
