package pod.cli.gcs

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update
import pod.cli.json.OnBoard
import pod.cli.planOf
import pod.cli.json.PlanProgress
import pod.cli.json.PlanTransfer
import pod.mavlink.MavlinkVehicle
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.TransferProgress
import pod.mavlink.plan.PlanListException
import pod.mavlink.plan.PlanSpeeds
import pod.mavlink.plan.QgcPlan
import java.util.concurrent.ConcurrentHashMap

/**
 * The plans of a fleet's vehicles, for every page (one per fleet: `fleet.service(PlanDesk::class)`):
 * uploads of dropped files and downloads of what a vehicle holds, one at a time per vehicle, with
 * their progress in [progress] and the lists last downloaded in [onBoard]. Each transfer's outcome
 * goes to the fleet's log; a refused one throws in the vehicle's words, for the page's reply.
 */
internal class PlanDesk(private val fleet: GcsFleet) {
    private val _progress = MutableStateFlow<Map<Int, PlanProgress>>(emptyMap())
    private val _onBoard = MutableStateFlow<Map<Int, OnBoard>>(emptyMap())
    private val busy = ConcurrentHashMap<Int, String>()

    /** Per vehicle, its latest transfer's progress (its last one stays, marked finished). */
    val progress: StateFlow<Map<Int, PlanProgress>> = _progress.asStateFlow()

    /** Per vehicle, what it held when last downloaded (after each upload too). */
    val onBoard: StateFlow<Map<Int, OnBoard>> = _onBoard.asStateFlow()

    /** Sends [file]'s lists to vehicle [sysid], then downloads what it holds for the map; returns what went. */
    suspend fun upload(sysid: Int, file: PlanFile): String {
        val vehicle = fleet.vehicle(sysid)
        return exclusive(sysid, "uploading ${file.name}") {
            val lists = try {
                file.lists(vehicle.identity.value.autopilot)
            } catch (e: GcsRequestException) {
                fleet.logEvent(PlanTransfer(sysid, file.name, "upload", ok = false, error = e.message))
                throw e
            }
            val sent = transfer(sysid, file.name, "upload", "uploading", logged = true) { report ->
                lists.associate { (type, items) ->
                    report(type, vehicle.mission.uploading(items, type))
                    type.name.lowercase() to items.size
                }
            }
            // What the map shows is what the vehicle holds, read back, not what was meant to go.
            val shown = try {
                downloadLocked(vehicle, logged = false)
                ""
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                "; the map could not read it back: ${e.message}"
            }
            val warnings = file.warnings.joinToString("") { "; warning: $it" }
            "uploaded ${file.name} to vehicle $sysid: " + sent.entries.joinToString(", ") { (list, n) -> "$n $list item" + if (n == 1) "" else "s" } + warnings + shown
        }
    }

    /** Downloads vehicle [sysid]'s three lists and shows them on the map; returns them as a plan. */
    suspend fun show(sysid: Int): QgcPlan {
        val vehicle = fleet.vehicle(sysid)
        return exclusive(sysid, "reading what it holds") { downloadLocked(vehicle, logged = true) }
    }

    /** [show], and the plan gets the speed the vehicle flies by default: the .plan file to save. */
    suspend fun download(sysid: Int): QgcPlan {
        val vehicle = fleet.vehicle(sysid)
        // The file records the speed the vehicle flies by default, as `pod mission download` writes it.
        return exclusive(sysid, "downloading its plan") { PlanSpeeds.from(vehicle, downloadLocked(vehicle, logged = true)) }
    }

    /**
     * [download] within [exclusive]; [logged]: its progress is shown and its outcome logged (not when
     * it reads back what an upload sent, which stays the transfer shown).
     */
    private suspend fun downloadLocked(vehicle: MavlinkVehicle, logged: Boolean): QgcPlan {
        val sysid = vehicle.systemId
        val lists = HashMap<MissionType, List<MissionItem>>()
        transfer(sysid, ON_BOARD, "download", "downloading", logged) { report ->
            LISTS.associate { type ->
                lists[type] = report(type, vehicle.mission.downloading(type))?.items.orEmpty()
                type.name.lowercase() to lists.getValue(type).size
            }
        }
        val plan = try {
            planOf(vehicle, lists)
        } catch (e: PlanListException) {
            throw GcsRequestException("vehicle $sysid's lists cannot be read as a plan: ${e.message}")
        }
        _onBoard.update { it + (sysid to OnBoardShapes.of(sysid, plan, lists.getValue(MissionType.MISSION))) }
        return plan
    }

    /**
     * Runs [work], which moves lists through the `report` it is given (a list's transfer flow,
     * collected to its end, its last progress returned); when [logged], keeps [progress] up to date
     * and logs how it ended. Returns what [work] returned: items per list.
     */
    private suspend fun transfer(
        sysid: Int,
        file: String,
        action: String,
        verb: String,
        logged: Boolean,
        work: suspend (report: suspend (MissionType, Flow<TransferProgress>) -> TransferProgress?) -> Map<String, Int>,
    ): Map<String, Int> {
        fun show(p: PlanProgress) {
            if (logged) _progress.update { it + (sysid to p) }
        }
        var last = PlanProgress(sysid, file, verb, "mission", 0, 0)
        show(last)
        try {
            val items = work { type, flow ->
                var final: TransferProgress? = null
                flow.collect { p ->
                    if (p.waiting == null) final = p
                    last = PlanProgress(sysid, file, verb, type.name.lowercase(), p.done, p.total, p.waiting)
                    show(last)
                }
                final
            }
            show(last.copy(finished = true))
            if (logged) fleet.logEvent(PlanTransfer(sysid, file, action, ok = true, items = items))
            return items
        } catch (e: CancellationException) {
            show(last.copy(finished = true, failed = true, waiting = null))
            throw e
        } catch (e: Exception) {
            show(last.copy(finished = true, failed = true, waiting = null))
            if (logged) fleet.logEvent(PlanTransfer(sysid, file, action, ok = false, error = e.message ?: e::class.simpleName))
            throw e
        }
    }

    /** Runs [block] as vehicle [sysid]'s only plan transfer; a second one is refused, not queued. */
    private suspend fun <T> exclusive(sysid: Int, what: String, block: suspend () -> T): T {
        val running = busy.putIfAbsent(sysid, what)
        if (running != null) throw GcsRequestException("vehicle $sysid is busy $running: try again when it is done")
        try {
            return block()
        } finally {
            busy.remove(sysid)
        }
    }

    companion object {
        /** The lists a plan holds, in the order QGC sends them. */
        val LISTS = listOf(MissionType.MISSION, MissionType.FENCE, MissionType.RALLY)

        /** What [PlanProgress.file] says for a download. */
        const val ON_BOARD = "its plan"
    }
}
