package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.comparables.shouldBeGreaterThan
import io.kotest.matchers.comparables.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.flow.last
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.Autopilot
import pod.mavlink.GroundStationConfig
import pod.mavlink.VehicleTiming
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionTimeout
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.TransferTiming
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/** The items MAVSDK printed for its [upload]-th incoming list, once it reported the list complete. */
private suspend fun JsonPeer.received(upload: Int): Pair<String, List<MissionItem>> {
    val done = await("upload") { it["upload"] == "$upload" }
    val items = events.replayCache.filter { it["event"] == "item" && it["upload"] == "$upload" }.map { it.toMissionItem() }
    items.size shouldBe done.getValue("count").toInt()
    return done.getValue("result") to items
}

/**
 * Freezes [process] with SIGSTOP on the first [freezeOnce] and thaws it [pause] later, as a
 * scheduler hiccup or a radio fade would hold up a real vehicle's answers (queued, not lost).
 */
private class Freezer(private val process: Process, private val scope: CoroutineScope, private val pause: Duration) {
    var frozen = false
        private set

    /** Called from a transfer's progress callback: the freeze is in effect before the transfer goes on. */
    fun freezeOnce() {
        if (frozen) return
        frozen = true
        process.signal("STOP")
        scope.launch(Dispatchers.IO) {
            delay(pause)
            process.signal("CONT")
        }
    }
}

/** Sends signal [name] (STOP, CONT) to this process with kill(1). */
private fun Process.signal(name: String) {
    ProcessBuilder("kill", "-$name", pid().toString()).start().waitFor()
}

class MavsdkVehicleSpec : StringSpec({

    "a 40-item mission uploaded by Pod reaches MAVSDK's MissionRawServer field for field, and downloads back identical" {
        withMavsdkVehicle { vehicle, peer ->
            // MAVSDK's autopilot heartbeat says MAV_TYPE_GENERIC / MAV_AUTOPILOT_GENERIC.
            vehicle.identity.value.autopilot shouldBe Autopilot.GENERIC
            val items = variedMission(40)
            vehicle.mission.upload(items)
            val (result, received) = peer.received(1)
            result shouldBe "SUCCESS"
            received shouldBe items
            // MissionRawServer in MAVSDK 4.1 serves downloads (MISSION_REQUEST_LIST), in order.
            vehicle.mission.download() shouldBe items
        }
    }

    "fence and rally lists go to MAVSDK's server apart from the mission, and clear empties only its own list" {
        withMavsdkVehicle { vehicle, peer ->
            val mission = variedMission(12)
            vehicle.mission.upload(mission)
            vehicle.mission.upload(fence(5), MissionType.FENCE)
            vehicle.mission.upload(rally(3), MissionType.RALLY)
            peer.received(2) shouldBe ("SUCCESS" to fence(5))
            peer.received(3) shouldBe ("SUCCESS" to rally(3))
            vehicle.mission.download(MissionType.FENCE) shouldBe fence(5)
            vehicle.mission.download(MissionType.RALLY) shouldBe rally(3)
            vehicle.mission.download() shouldBe mission
            vehicle.mission.clear(MissionType.FENCE)
            vehicle.mission.download(MissionType.FENCE).shouldBeEmpty()
            vehicle.mission.download(MissionType.RALLY) shouldBe rally(3)
            vehicle.mission.download() shouldBe mission
            vehicle.mission.clear()
            withTimeout(5.seconds) { peer.await("clear") { it["mission_type"] == "0" } }
            vehicle.mission.download().shouldBeEmpty()
        }
    }

    "upload and download ride out a MAVSDK vehicle that freezes for 200 ms (as each transfer starts)" {
        withMavsdkVehicle { vehicle, peer ->
            val items = variedMission(250)
            val pause = 200.milliseconds
            try {
                coroutineScope {
                    // Pod times out after ~40 ms here, resends, and then gets every queued answer at once.
                    // Frozen as the transfer starts: freezing it from the progress flow (at item 20, say)
                    // can come too late, as the in-place driver moves 250 items in about 10 ms and the
                    // flow's collector may see item 20 only once the transfer is over (CI saw 11 ms).
                    val upload = Freezer(peer.process, this, pause)
                    val uploadStarted = TimeSource.Monotonic.markNow()
                    upload.freezeOnce()
                    vehicle.mission.uploading(items).collect { }
                    upload.frozen shouldBe true
                    uploadStarted.elapsedNow() shouldBeGreaterThan pause
                    peer.received(1) shouldBe ("SUCCESS" to items)

                    // The download's first answers go unanswered while the vehicle is frozen, likewise.
                    val download = Freezer(peer.process, this, pause)
                    val downloadStarted = TimeSource.Monotonic.markNow()
                    download.freezeOnce()
                    vehicle.mission.downloading().last().items shouldBe items
                    download.frozen shouldBe true
                    downloadStarted.elapsedNow() shouldBeGreaterThan pause
                }
            } finally {
                peer.process.signal("CONT") // never leave it frozen, whatever failed
            }
        }
    }

    "set-current moves MAVSDK's current mission item" {
        withMavsdkVehicle { vehicle, peer ->
            vehicle.mission.upload(variedMission(10))
            vehicle.mission.setCurrent(7)
            withTimeout(5.seconds) { peer.await("current") { it["seq"] == "7" } }
        }
    }

    "a MAVSDK vehicle without a mission server makes download and upload fail with MissionTimeout within the retry budget" {
        val quick = TransferTiming(initialTimeout = 100.milliseconds, minTimeout = 50.milliseconds, maxTimeout = 200.milliseconds, retries = 3, patience = kotlin.time.Duration.ZERO)
        withMavsdkVehicle("--no-mission-server", station = GroundStationConfig(vehicleTiming = VehicleTiming(transfers = quick))) { vehicle, _ ->
            // 100 ms, then 200, 200, 200 (backed off, capped): 0.7 s in all.
            for ((operation, waitingFor) in listOf("download" to "the item count", "upload" to "the first item request")) {
                val started = TimeSource.Monotonic.markNow()
                val error = shouldThrow<MissionTimeout> {
                    if (operation == "download") vehicle.mission.download() else vehicle.mission.upload(variedMission(5))
                }
                val took = started.elapsedNow()
                error.retries shouldBe 3
                error.waitingFor shouldBe waitingFor
                error.type shouldBe MissionType.MISSION
                took shouldBeGreaterThan 600.milliseconds
            }
        }
    }
})
