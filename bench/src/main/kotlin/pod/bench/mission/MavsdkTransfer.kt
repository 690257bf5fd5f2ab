package pod.bench.mission

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.runInterruptible
import pod.bench.RelayedVehicle
import pod.bench.freeUdpPort
import pod.mavlink.mission.MissionItem
import java.io.File
import kotlin.time.Duration.Companion.seconds

/** Beyond the script's own deadlines, how long the harness waits before it kills the peer. */
private val GRACE = 15.seconds

/**
 * MAVSDK 4.1 (MissionRaw), as a subprocess, as the ground station of one run: the peer starts and
 * listens first, then the relay and vehicle start sending to it. Upload and download times are the
 * script's own (time.monotonic around each MissionRaw call), so Python's start-up and discovery
 * are not counted.
 */
suspend fun mavsdkTransfer(setup: MavsdkSetup, cell: Cell, seed: Long, items: List<MissionItem>, limits: Limits): TransferRun = coroutineScope {
    val itemsFile = File.createTempFile("mission-bench-", ".json").apply { writeText(items.toMavsdkJson()); deleteOnExit() }
    val port = freeUdpPort()
    val peer = MavsdkPeer(setup, port, itemsFile, limits, "${cell.label}, seed $seed")
    var rig: RelayedVehicle? = null
    fun failed(what: String) = TransferRun(Station.MAVSDK, cell, seed, null, null, setupError = what)
    suspend fun await(event: String, limit: kotlin.time.Duration) = runInterruptible(Dispatchers.IO) { peer.await(event, limit) }
    try {
        val ready = await("ready", limits.discovery + GRACE)
        if (ready?.get("event") != "ready") return@coroutineScope failed("MAVSDK peer did not start: ${ready ?: "nothing within ${limits.discovery + GRACE}"}")
        rig = startCellVehicle(this, cell, seed, port)
        val system = await("system", limits.discovery + GRACE)
        if (system?.get("event") != "system" || system["sysid"] == null) return@coroutineScope failed("vehicle not discovered: ${system ?: "nothing within ${limits.discovery + GRACE}"}")

        val upload = step(await("uploaded", limits.transfer + GRACE), "uploaded", limits)
        var download: Step? = null
        var mismatch: String? = null
        if (upload.ok) {
            download = step(await("downloaded", limits.transfer + GRACE), "downloaded", limits)
            if (download.ok) mismatch = missionMismatch(cell.flavour, items, peer.items.map { it.toMissionItem() })
        }
        // MissionRaw's result name alone ("TIMEOUT") does not say what it was waiting for; its log does.
        fun explained(step: Step?) = if (step == null || step.ok) step else step.copy(error = step.error + (peer.lastWarning()?.let { "; MAVSDK log: $it" } ?: ""))
        TransferRun(
            Station.MAVSDK, cell, seed, explained(upload), explained(download), mismatch,
            droppedToGcs = rig.droppedToGcs, droppedToVehicle = rig.droppedToVehicle,
        )
    } finally {
        peer.close()
        rig?.close()
        itemsFile.delete()
        coroutineContext.cancelChildren()
    }
}

/** The script's report of one transfer as a [Step]: its MissionRaw result name on failure. */
private fun step(report: Map<String, String>?, event: String, limits: Limits): Step = when {
    report == null -> Step(false, (limits.transfer + GRACE).inWholeMilliseconds / 1e3, "HARNESS_TIMEOUT: the peer printed nothing within ${limits.transfer + GRACE}; killed")
    report["event"] != event -> Step(false, report["seconds"]?.toDoubleOrNull() ?: Double.NaN, "PEER_EXITED: $report")
    report["result"] == "SUCCESS" -> Step(true, report.getValue("seconds").toDouble())
    report["result"] == "WATCHDOG" -> Step(false, report.getValue("seconds").toDouble(), "WATCHDOG: no outcome within ${limits.transfer} (script's watchdog)")
    else -> Step(false, report["seconds"]?.toDoubleOrNull() ?: Double.NaN, "${report["result"]} (MissionRaw result)")
}
