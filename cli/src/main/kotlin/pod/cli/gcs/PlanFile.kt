package pod.cli.gcs

import pod.core.PodException
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.InvalidMission
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.MissionValidation
import pod.mavlink.mission.WplFile
import pod.mavlink.plan.PlanOnVehicle
import pod.mavlink.plan.QgcPlan
import pod.mavlink.plan.QgcPlanFile
import pod.mavlink.plan.WplOnVehicle

/**
 * A plan file dropped on the page, read as `pod mission upload` reads one from disk: a QGC `.plan`
 * (mission, fence and rally lists, replacing all three as QGC's upload does) or a QGC WPL 110 text
 * (one [wplType] list; line 0 of a mission is home, ArduPilot's convention). Every problem is a
 * [GcsRequestException] that starts with the file's [name], so the page can show it as it is.
 */
internal class PlanFile private constructor(
    /** The file's name as the page gave it (its last path segment, at most [MAX_NAME] characters). */
    val name: String,
    private val plan: QgcPlan?,
    private val wpl: List<MissionItem>?,
    private val wplType: MissionType,
) {
    /** What reading the file changed or could not keep (a QGC survey expanded to its items). */
    val warnings: List<String> get() = plan?.warnings.orEmpty()

    /**
     * The lists to send a vehicle of [autopilot], in order, each checked as the vehicle would check
     * it: nothing is sent when any list is bad.
     */
    fun lists(autopilot: Autopilot): List<Pair<MissionType, List<MissionItem>>> {
        val lists = plan?.let { PlanOnVehicle.lists(it, autopilot) } ?: listOf(wplType to WplOnVehicle.toVehicle(wpl!!, wplType, autopilot))
        lists.forEach { (type, items) ->
            try {
                MissionValidation.check(type, items)
            } catch (e: InvalidMission) {
                throw GcsRequestException("$name (${type.name.lowercase()} list): ${e.message}")
            }
        }
        // An empty .plan or WPL file would clear the vehicle's lists: a dropped file should not do that by accident.
        if (lists.all { it.second.isEmpty() }) throw GcsRequestException("$name holds no items: uploading it would clear the vehicle's lists")
        return lists
    }

    companion object {
        /** The largest file read: escaped into its request (quotes and line ends take two characters) it stays within the WebSocket's 4 MiB frame. */
        const val MAX_CHARS = 2 * 1024 * 1024
        const val MAX_NAME = 120

        /** Reads [text], the file the page named [fileName]; [wplType] is the list a WPL file fills. */
        fun read(fileName: String, text: String, wplType: MissionType = MissionType.MISSION): PlanFile {
            val name = fileName.substringAfterLast('/').substringAfterLast('\\').take(MAX_NAME).ifBlank { "the file" }
            if (text.length > MAX_CHARS) throw GcsRequestException("$name is too large for a plan file (${text.length / 1024} KiB)")
            val kind = kindOf(name) ?: throw GcsRequestException("$name: not a plan file: the page takes QGC .plan files and QGC WPL 110 files (.waypoints, .txt, .mission)")
            return try {
                when (kind) {
                    Kind.PLAN -> PlanFile(name, QgcPlanFile.read(text), null, wplType)
                    Kind.WPL -> PlanFile(name, null, WplFile.read(text, wplType), wplType)
                }
            } catch (e: PodException) {
                // QgcPlanFormatException and WplFormatException name the JSON path or the line.
                throw GcsRequestException("$name: ${e.message}")
            }
        }

        private enum class Kind { PLAN, WPL }

        private fun kindOf(name: String): Kind? = when (name.substringAfterLast('.', "").lowercase()) {
            "plan" -> Kind.PLAN
            "waypoints", "txt", "mission" -> Kind.WPL
            else -> null
        }
    }
}
