package pod.e2e

import com.github.ajalt.clikt.core.parse
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.withContext
import pod.cli.Pod
import pod.cli.json.Event
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.WplFile
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.nio.file.Files
import java.nio.file.Path

/**
 * A QGC WPL mission's line 0 is home, by ArduPilot's convention: a PX4 vehicle must not get it as a
 * waypoint at ground level (QGC leaves it out for PX4), and a download from PX4 writes one back.
 */
class WplCliSpec : StringSpec({
    // Line 0 home (absolute altitude, as Mission Planner writes it), then a take-off and three waypoints.
    val home = MissionItem(seq = 0, frame = 0, command = 16, current = true, x = 411_780_460, y = -85_957_860, z = 120f)
    val flight = listOf(MissionItem(seq = 1, frame = 3, command = 22, z = 20f)) +
        waypoints(3).map { it.copy(seq = it.seq + 2, current = false) }
    val file = listOf(home) + flight

    "pod mission upload FILE to PX4 leaves line 0 (home) out; download FILE writes the vehicle's home back as line 0" {
        withCliVehicle(SimVehicleConfig(systemId = 17, autopilot = Autopilot.PX4)) { sim, dir, connect ->
            val upload = dir.resolve("mission.waypoints").also { WplFile.write(it, file) }
            val out = Captured()
            withContext(Dispatchers.IO) { Pod(out).parse(listOf("mission", "upload", upload.toString()) + connect) }
            out.events.last().shouldBeInstanceOf<Event.Done>().items shouldBe 4
            // Before: 5 items, item 0 a waypoint at the ground that PX4 flew first and never left.
            sim.missionServer.list(MissionType.MISSION) shouldBe flight.map { it.copy(seq = it.seq - 1) }

            val download = dir.resolve("back.waypoints")
            withContext(Dispatchers.IO) { Pod(Captured()).parse(listOf("mission", "download", download.toString()) + connect) }
            val back = WplFile.read(download)
            back.drop(1) shouldBe flight
            val home = sim.config.home
            (back.first().seq to back.first().command) shouldBe (0 to 16)
            (back.first().latitude to back.first().longitude) shouldBe (Math.round(home.latitude * 1e7) / 1e7 to Math.round(home.longitude * 1e7) / 1e7)
        }
    }

    "pod mission upload FILE to ArduPilot sends line 0 as item 0, where ArduPilot keeps home" {
        withCliVehicle(SimVehicleConfig(systemId = 18)) { sim, dir, connect ->
            val upload = dir.resolve("mission.waypoints").also { WplFile.write(it, file) }
            withContext(Dispatchers.IO) { Pod(Captured()).parse(listOf("mission", "upload", upload.toString()) + connect) }
            sim.missionServer.list(MissionType.MISSION).size shouldBe file.size
        }
    }
})

/** A simulated vehicle of [config] sending to a free port, a scratch folder and the `pod` options that reach the vehicle; both go afterwards. */
private suspend fun withCliVehicle(config: SimVehicleConfig, block: suspend (SimVehicle, Path, List<String>) -> Unit) = coroutineScope {
    val port = freePort()
    val sim = SimVehicle(config.copy(gcs = "udpout://127.0.0.1:$port"))
    val dir = Files.createTempDirectory("pod-wpl-cli")
    try {
        sim.start(this)
        block(sim, dir, listOf("--connect", "udpin:127.0.0.1:$port", "--json"))
    } finally {
        sim.stop()
        dir.toFile().deleteRecursively()
    }
}
