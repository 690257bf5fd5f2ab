package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.ArduPilotMissionStorage
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.WplFile
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.nio.file.Files
import kotlin.time.Duration.Companion.seconds

class LegacyMissionItemSpec : StringSpec({

    "pymavlink's mavwp uploads with legacy MISSION_ITEM and downloads with MISSION_REQUEST from a simulated ArduPilot" {
        coroutineScope {
            val port = freeUdpPort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 41, autopilot = Autopilot.ARDUPILOT, gcs = "udpout://127.0.0.1:$port"))
            val file = Files.createTempFile("pod-legacy", ".waypoints")
            val items = listOf(
                MissionItem(0, 0, 16, x = 411_780_460, y = -85_957_860, z = 120f),
                MissionItem(1, 3, 22, x = 411_780_460, y = -85_957_860, z = 30f),
                MissionItem(2, 3, 16, x = 411_790_000, y = -85_950_000, z = 40f),
                MissionItem(3, 2, 178, param1 = 1f, param2 = 8f, param3 = -1f),
                MissionItem(4, 3, 16, x = 411_800_000, y = -85_940_000, z = 40f),
                MissionItem(5, 2, 20),
            )
            WplFile.write(file, items)
            val peer = Python.startJson("mavwp_upload.py", port, 41, file)
            try {
                sim.start(this)
                withTimeout(30.seconds) {
                    peer.await("uploaded").getValue("result") shouldBe "0" // MAV_MISSION_ACCEPTED
                    val held = sim.missionServer.list(MissionType.MISSION)
                    // Latitude and longitude went as float degrees: within a float's precision of what was meant.
                    held.size shouldBe items.size
                    for ((kept, sent) in held.zip(ArduPilotMissionStorage.stored(items, fixedWing = false)).drop(1)) {
                        kept.copy(x = 0, y = 0) shouldBe sent.copy(x = 0, y = 0)
                        kept.latitude shouldBe (sent.latitude plusOrMinus 1e-5)
                        kept.longitude shouldBe (sent.longitude plusOrMinus 1e-5)
                    }
                    peer.await("downloaded").getValue("count") shouldBe "${items.size}"
                    val back = peer.events.replayCache.filter { it["event"] == "item" }
                    back.map { it.getValue("msg") }.distinct() shouldBe listOf("MISSION_ITEM")
                    back[2].getValue("x").toDouble() shouldBe (41.179 plusOrMinus 1e-5)
                }
            } finally {
                peer.stop()
                sim.stop()
                Files.deleteIfExists(file)
            }
        }
    }
})
