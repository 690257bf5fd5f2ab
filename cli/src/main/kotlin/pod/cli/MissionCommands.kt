package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.choice
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.units.Location
import kotlin.time.Duration.Companion.seconds
import pod.cli.json.Event
import pod.core.units.m
import pod.mavlink.MavFrames
import pod.mavlink.MavlinkVehicle
import pod.mavlink.firmware.Firmware
import pod.mavlink.mission.MissionWarnings
import pod.mavlink.mission.InvalidMission
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.MissionValidation
import pod.mavlink.mission.TransferProgress
import pod.mavlink.mission.WplFile
import pod.core.vehicle.Autopilot
import pod.mavlink.plan.PlanListException
import pod.mavlink.plan.PlanOnVehicle
import pod.mavlink.plan.PlanSpeeds
import pod.mavlink.plan.QgcPlan
import pod.mavlink.plan.QgcPlanFile
import pod.mavlink.plan.WplOnVehicle
import java.io.IOException
import java.nio.file.Path

/** `pod mission`: upload, download and clear a vehicle's mission, fence or rally list. */
internal class MissionGroup(out: Output) : CliktCommand(name = "mission") {
    init {
        subcommands(MissionUploadCommand(out), MissionDownloadCommand(out), MissionClearCommand(out))
    }

    override fun help(context: Context): String = "Upload, download or clear a vehicle's mission, fence or rally points (QGC WPL 110 files, or QGC .plan files for all three at once)."

    override fun run() = Unit
}

/** Options every `pod mission` command shares, on top of picking the vehicle. */
internal abstract class MissionAction(out: Output, name: String) : VehicleCommandBase(out, name) {
    /** Interrupted, the transfer is cancelled (the vehicle is told so); the vehicle flies on as it was. */
    override suspend fun afterInterrupt(vehicle: MavlinkVehicle): String = "transfer cancelled; the vehicle's flight is unchanged"

    protected val type by option("--type", help = "which list").choice("mission" to MissionType.MISSION, "fence" to MissionType.FENCE, "rally" to MissionType.RALLY)
        .default(MissionType.MISSION, defaultForHelp = "mission")

    /**
     * Collects [transfer] to its end, reporting its progress: a [TransferProgressView] for people (a
     * bar at a terminal, a few lines elsewhere, once the total is known), a JSON line per item for
     * scripts; a transfer that waits before it starts says why, as vehicle [sysid]'s. Returns the last
     * progress (a download's carries the list).
     */
    protected suspend fun withProgress(sysid: Int, action: String, transfer: Flow<TransferProgress>): TransferProgress? {
        var last: TransferProgress? = null
        // A transfer that must wait before it starts says why (a vehicle still holding an abandoned upload).
        fun waiting(p: TransferProgress): Boolean {
            val reason = p.waiting ?: return false
            if (json) emit(Event.Waiting(sysid, reason)) else out.line("vehicle $sysid: waiting: $reason")
            return true
        }
        if (json) {
            var shown = -1
            transfer.collect { p ->
                if (waiting(p)) return@collect
                last = p
                if (p.done != shown) {
                    shown = p.done
                    emit(Event.Progress(action, p.done, p.total))
                }
            }
            return last
        }
        val view = TransferProgressView(out, action)
        return coroutineScope {
            val ticker = if (view.animated) launch { while (true) { delay(TransferProgressView.TICK); view.tick() } } else null
            try {
                transfer.collect {
                    if (waiting(it)) return@collect
                    last = it
                    view.update(it)
                }
                last
            } finally {
                ticker?.cancel()
                view.finish()
            }
        }
    }
}

/** `pod mission upload FILE`: one WPL list, or a .plan file's mission, fence and rally lists. */
internal class MissionUploadCommand(out: Output) : MissionAction(out, "upload") {
    private val file by argument(help = "QGC WPL 110 file, or a QGC .plan file (mission, fence and rally; --type is ignored)")
    private val allowEmpty by option("--allow-empty", help = "upload a file with no items, which clears the vehicle's list").flag()

    override fun help(context: Context): String = "Upload a QGC WPL 110 file, or a QGC .plan file's mission, fence and rally points, to a vehicle."

    private var lists: List<Pair<MissionType, List<MissionItem>>> = emptyList()
    private var plan: QgcPlan? = null

    // The whole file is read and checked as the vehicle would check it before any link is opened.
    override fun prepare() {
        lists = if (LocalFiles.isPlan(file)) {
            // A .plan replaces all three lists, as QGC's upload does: an empty fence or rally list clears the vehicle's.
            val read = LocalFiles.readPlan(file)
            read.warnings.forEach { if (json) emit(Event.Warning("$file: $it")) else out.line("warning: $file: $it") }
            plan = read
            // Checked as the file numbers its items; an ArduPilot vehicle gets a home item before them (act).
            PlanOnVehicle.lists(read, Autopilot.PX4)
        } else {
            listOf(type to LocalFiles.readWpl(file, type))
        }
        lists.forEach { (type, items) ->
            try {
                MissionValidation.check(type, items)
            } catch (e: InvalidMission) {
                badInput("$file (${type.name.lowercase()} list): ${e.message}")
            }
        }
        if (lists.all { it.second.isEmpty() } && !allowEmpty) {
            val which = if (lists.size == 1) "${type.name.lowercase()} list" else "mission, fence and rally lists"
            badInput("$file holds no items: uploading it would clear the vehicle's $which; use 'pod mission clear', or pass --allow-empty")
        }
    }

    private fun warnSuspiciousItems(vehicleHome: Location?) {
        suspiciousItems(lists, plan, vehicleHome).forEach { if (json) emit(Event.Warning("$file: $it")) else out.line("warning: $file: $it") }
    }

    override suspend fun act(vehicle: MavlinkVehicle) {
        warnSuspiciousItems(vehicle.telemetry.home.value)
        val autopilot = vehicle.identity.value.autopilot
        // A .plan has no home item and a WPL file's mission has one in line 0: each as this autopilot keeps home.
        lists = plan?.let { PlanOnVehicle.lists(it, autopilot) } ?: lists.map { (type, items) -> type to WplOnVehicle.toVehicle(items, type, autopilot) }
        lists.forEach { (type, items) -> withProgress(vehicle.systemId, "uploading", vehicle.mission.uploading(items, type)) }
        val total = lists.sumOf { it.second.size }
        val message = if (lists.size == 1) {
            val (type, items) = lists.single()
            val list = type.name.lowercase()
            if (items.isEmpty()) "uploaded an empty $list list: cleared the $list list of vehicle ${vehicle.systemId}" else "uploaded ${items(items.size, type)} to vehicle ${vehicle.systemId}"
        } else {
            "uploaded ${lists.joinToString(", ") { (type, items) -> items(items.size, type) }} to vehicle ${vehicle.systemId}"
        }
        finish(message, vehicle, action = "upload", items = total)
    }
}

/**
 * Says which of the mission's items sit below home or far away ([MissionWarnings]), measured from
 * the vehicle's home, else the file's (a .plan's planned home, a WPL file's line 0 in frame 0).
 */
private fun suspiciousItems(lists: List<Pair<MissionType, List<MissionItem>>>, plan: QgcPlan?, vehicleHome: Location?): List<String> {
    val mission = plan?.mission ?: lists.singleOrNull { it.first == MissionType.MISSION }?.second ?: return emptyList()
    val lineZero = if (plan == null) mission.firstOrNull()?.takeIf { it.seq == 0 && it.frame == MavFrames.GLOBAL && (it.x != 0 || it.y != 0) } else null
    val fileHome = plan?.plannedHome?.let { Location(it.latitude, it.longitude, it.altitude.m) }
        ?: lineZero?.let { Location(it.latitude, it.longitude, it.z.toDouble().m) }
    return MissionWarnings.of(if (lineZero != null) mission.drop(1) else mission, vehicleHome ?: fileHome)
}

/** `pod mission download FILE`. */
internal class MissionDownloadCommand(out: Output) : MissionAction(out, "download") {
    private val file by argument(help = "QGC WPL 110 file to write, or a .plan file for all three lists (--type is ignored)")

    override fun help(context: Context): String = "Download a vehicle's list into a QGC WPL 110 file, or all three lists into a QGC .plan file."

    // A path that cannot be written fails now, not after a transfer that may take a minute.
    override fun prepare() {
        LocalFiles.checkWritable(file)
    }

    override suspend fun act(vehicle: MavlinkVehicle) {
        if (LocalFiles.isPlan(file)) return downloadPlan(vehicle)
        val items = withProgress(vehicle.systemId, "downloading", vehicle.mission.downloading(type))?.items.orEmpty()
        try {
            WplFile.write(Path.of(file), WplOnVehicle.toFile(items, type, vehicle.identity.value.autopilot, homeFor(vehicle, items)))
        } catch (e: IOException) {
            fail("cannot write $file: ${e.message}")
        }
        finish("downloaded ${items(items.size, type)} from vehicle ${vehicle.systemId} to $file", vehicle, action = "download", items = items.size)
    }

    // Line 0 of a mission file is home; where the vehicle's own item 0 is not (PX4), the home it reports once its estimator has an origin.
    private suspend fun homeFor(vehicle: MavlinkVehicle, items: List<MissionItem>): Location? {
        if (items.isEmpty() || type != MissionType.MISSION || Firmware.of(vehicle.identity.value).itemZeroIsHome) return null
        return withTimeoutOrNull(HOME_WAIT) { vehicle.telemetry.home.filterNotNull().first() }
    }

    // All three lists into one .plan file; ArduPilot's mission item 0 is its home, the file's planned home.
    // What the vehicle tells of itself goes in too (autopilot, airframe, home, default speed); what it
    // does not is left out, never written as 0.
    private suspend fun downloadPlan(vehicle: MavlinkVehicle) {
        val lists = listOf(MissionType.MISSION, MissionType.FENCE, MissionType.RALLY).associateWith { type ->
            withProgress(vehicle.systemId, "downloading", vehicle.mission.downloading(type))?.items.orEmpty()
        }
        val plan = try {
            PlanSpeeds.from(vehicle, planOf(vehicle, lists, HOME_WAIT))
        } catch (e: PlanListException) {
            fail("vehicle ${vehicle.systemId}'s lists cannot be written as a .plan file: ${e.message}")
        }
        try {
            QgcPlanFile.write(Path.of(file), plan)
        } catch (e: IOException) {
            fail("cannot write $file: ${e.message}")
        }
        val summary = lists.entries.joinToString(", ") { (type, items) -> items(items.size, type) }
        finish("downloaded $summary from vehicle ${vehicle.systemId} to $file", vehicle, action = "download", items = lists.values.sumOf { it.size })
    }
}

/**
 * How long `pod mission download` waits for the vehicle's home (the station asked for it on
 * discovery): a PX4 WPL file's line 0, a .plan's planned home (left out when none comes).
 */
private val HOME_WAIT = 5.seconds

/** `pod mission clear`. */
internal class MissionClearCommand(out: Output) : MissionAction(out, "clear") {
    override fun help(context: Context): String = "Delete a vehicle's mission, fence or rally list."

    override suspend fun act(vehicle: MavlinkVehicle) {
        vehicle.mission.clear(type)
        finish("cleared the ${type.name.lowercase()} list of vehicle ${vehicle.systemId}", vehicle, action = "clear", items = 0)
    }
}

/** "1 mission item", "25 fence items". */
private fun items(count: Int, type: MissionType): String = "$count ${type.name.lowercase()} item" + if (count == 1) "" else "s"
