package pod.bench.mission

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.bench.RelayedVehicle
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.VehicleTiming
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.TransferTiming
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * Pod's GroundStation, in this JVM, as the ground station of one run: discovers the vehicle (not
 * timed), uploads [items] (timed), downloads them back (timed) and compares.
 */
suspend fun podTransfer(cell: Cell, seed: Long, items: List<MissionItem>, limits: Limits, timing: TransferTiming): TransferRun = coroutineScope {
    // Heartbeats cross the lossy relay too: at 30 % loss several in a row go missing now and then,
    // and the default 3 s would call the vehicle lost in the middle of a transfer.
    val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(lostAfter = 30.seconds, vehicleTiming = VehicleTiming(transfers = timing)))
    var rig: RelayedVehicle? = null
    try {
        rig = startCellVehicle(this, cell, seed, gcs.link.localPort)
        val vehicle = try {
            withTimeout(limits.discovery) { gcs.vehicles.first { VEHICLE_SYSTEM_ID in it } }.getValue(VEHICLE_SYSTEM_ID)
        } catch (e: TimeoutCancellationException) {
            return@coroutineScope TransferRun(Station.POD, cell, seed, null, null, setupError = "vehicle not discovered within ${limits.discovery}")
        }
        val upload = timed(limits.transfer) { vehicle.mission.upload(items, MissionType.MISSION) }
        var download: Step? = null
        var mismatch: String? = null
        if (upload.step.ok) {
            val back = timed(limits.transfer) { vehicle.mission.download(MissionType.MISSION) }
            download = back.step
            back.value?.let { mismatch = missionMismatch(cell.flavour, items, it) }
        }
        TransferRun(Station.POD, cell, seed, upload.step, download, mismatch, droppedToGcs = rig.droppedToGcs, droppedToVehicle = rig.droppedToVehicle)
    } finally {
        rig?.close()
        gcs.close()
        coroutineContext.cancelChildren()
    }
}

/** How long discovery may take, and each transfer. */
data class Limits(val discovery: Duration = 30.seconds, val transfer: Duration = 120.seconds)

private class Timed<T>(val step: Step, val value: T?)

/** Runs [block] within [limit]; any failure (a typed MissionException, VehicleLost, the limit) is recorded, not thrown. */
private suspend fun <T> timed(limit: Duration, block: suspend () -> T): Timed<T> {
    val mark = TimeSource.Monotonic.markNow()
    fun seconds() = mark.elapsedNow().inWholeMicroseconds / 1e6
    return try {
        val value = withTimeout(limit) { block() }
        Timed(Step(true, seconds()), value)
    } catch (e: TimeoutCancellationException) {
        Timed(Step(false, seconds(), "TimeoutCancellationException: no outcome within $limit (harness limit)"), null)
    } catch (e: CancellationException) {
        throw e
    } catch (e: Exception) {
        Timed(Step(false, seconds(), "${e::class.simpleName}: ${e.message}"), null)
    }
}
