package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.seconds

/** What mavsdk_gcs.py reported: the system it found and the items it downloaded. */
private class GcsRun(val system: Map<String, String>, val items: List<MissionItem>)

/**
 * Starts MAVSDK as a ground station listening on a loopback port (mavsdk_gcs.py), then a simulated
 * vehicle sending there; MAVSDK uploads [items] and downloads them back, both of which must
 * succeed. Runs [block] with the outcome while the vehicle still runs.
 */
private suspend fun mavsdkUploads(autopilot: Autopilot, items: List<MissionItem>, block: (GcsRun, SimVehicle) -> Unit) = coroutineScope {
    val port = freeUdpPort()
    val peer = Python.startJson("mavsdk_gcs.py", port, items.toJson(), 25, "--download")
    val sim = SimVehicle(SimVehicleConfig(systemId = 9, autopilot = autopilot, gcs = "udpout://127.0.0.1:$port"))
    try {
        withTimeout(15.seconds) { peer.await("ready") }
        sim.start(this)
        val run = withTimeout(20.seconds) {
            val system = peer.await("system")
            peer.await("uploaded")["result"] shouldBe "SUCCESS"
            peer.await("downloaded")["result"] shouldBe "SUCCESS"
            peer.await("done")
            GcsRun(system, peer.events.replayCache.filter { it["event"] == "item" }.map { it.toMissionItem() })
        }
        block(run, sim)
    } finally {
        peer.stop()
        sim.stop()
    }
}

class MavsdkGroundStationSpec : StringSpec({

    "MAVSDK uploads a 30-item mission into a simulated PX4 vehicle, which holds it as sent, and downloads it back" {
        val items = variedMission(30)
        mavsdkUploads(Autopilot.PX4, items) { run, sim ->
            run.system["sysid"] shouldBe "9"
            run.system["autopilot"] shouldBe "PX4"
            sim.missionServer.list(MissionType.MISSION) shouldBe items.map { it.copy(current = false) }
            run.items shouldBe items
        }
    }

    "MAVSDK uploads into a simulated ArduPilot vehicle through legacy MISSION_REQUESTs; item 0 becomes home, the rest ArduPilot's own form" {
        val items = variedMission(30)
        mavsdkUploads(Autopilot.ARDUPILOT, items) { run, sim ->
            run.system["autopilot"] shouldBe "ARDUPILOT"
            val home = pod.mavlink.mission.ArduPilotMissionStorage.stored(sim.missionServer.home!!, fixedWing = false)
            val kept = pod.mavlink.mission.ArduPilotMissionStorage.stored(items.drop(1), fixedWing = false)
            sim.missionServer.list(MissionType.MISSION) shouldBe listOf(home) + kept
            run.items shouldBe listOf(home.copy(current = true)) + kept
        }
    }
})
