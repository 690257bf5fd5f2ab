package pod.e2e

import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.parse
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.matchers.string.shouldNotContain
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.withContext
import pod.cli.Pod
import pod.cli.json.Event
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.WplFile
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.net.DatagramSocket
import java.net.InetAddress
import java.nio.file.Files
import kotlin.io.path.writeText

/** A UDP port free right now on 127.0.0.1 (the CLI binds it a moment later). */
internal fun freePort(): Int = DatagramSocket(0, InetAddress.getByName("127.0.0.1")).use { it.localPort }

/** A WPL mission file of [items]: line 0 the simulated vehicle's home, as the format has it, then [items] from line 1. */
private fun withHome(items: List<MissionItem>): List<MissionItem> {
    val home = SimVehicleConfig.DEFAULT_HOME
    val line0 = MissionItem(seq = 0, frame = 0, command = 16, current = true, x = Math.round(home.latitude * 1e7).toInt(), y = Math.round(home.longitude * 1e7).toInt(), z = home.altitude.meters.toFloat())
    return listOf(line0) + items.map { it.copy(seq = it.seq + 1) }
}

class MissionCliSpec : StringSpec({

    "pod mission upload, download and clear a simulated vehicle's list through WPL files" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 12, autopilot = Autopilot.PX4, gcs = "udpout://127.0.0.1:$port"))
            val dir = Files.createTempDirectory("pod-mission-cli")
            try {
                sim.start(this)
                val items = waypoints(25).map { it.copy(current = false) }
                val file = withHome(items) // line 0 is home, which PX4 does not get (WplOnVehicle)
                val upload = dir.resolve("plan.waypoints").also { WplFile.write(it, file) }
                val connect = listOf("--connect", "udpin:127.0.0.1:$port", "--json")
                val out = Captured()
                withContext(Dispatchers.IO) { Pod(out).parse(listOf("mission", "upload", upload.toString()) + connect) }
                val uploaded = out.events
                val done = uploaded.last().shouldBeInstanceOf<Event.Done>()
                (done.action to done.items) shouldBe ("upload" to 25)
                done.sysid shouldBe 12
                uploaded.filterIsInstance<Event.Progress>().last() shouldBe Event.Progress("uploading", 25, 25)
                sim.missionServer.list(MissionType.MISSION) shouldBe items

                val download = dir.resolve("back.waypoints")
                val downloaded = Captured()
                withContext(Dispatchers.IO) { Pod(downloaded).parse(listOf("mission", "download", download.toString()) + connect) }
                WplFile.read(download) shouldBe file // line 0 written back from the vehicle's home
                downloaded.events.last().shouldBeInstanceOf<Event.Done>().items shouldBe 25
                downloaded.events.filterIsInstance<Event.Progress>().last() shouldBe Event.Progress("downloading", 25, 25)

                val cleared = Captured()
                withContext(Dispatchers.IO) { Pod(cleared).parse(listOf("mission", "clear") + connect) }
                sim.missionServer.list(MissionType.MISSION).shouldBeEmpty()
                val clearedDone = cleared.events.single().shouldBeInstanceOf<Event.Done>()
                (clearedDone.action to clearedDone.items) shouldBe ("clear" to 0)

                // A header-only file clears the list only when asked to, and then says it cleared.
                withContext(Dispatchers.IO) { Pod(Lines()).parse(listOf("mission", "upload", upload.toString()) + connect) }
                val empty = dir.resolve("empty.waypoints").also { WplFile.write(it, emptyList()) }
                val refused = shouldThrow<CliktError> { withContext(Dispatchers.IO) { Pod(Lines()).parse(listOf("mission", "upload", empty.toString()) + connect) } }
                refused.statusCode shouldBe 2
                refused.message!! shouldContain "--allow-empty"
                sim.missionServer.list(MissionType.MISSION).size shouldBe 25
                val said = Lines()
                withContext(Dispatchers.IO) {
                    Pod(said).parse(listOf("mission", "upload", empty.toString(), "--allow-empty", "--connect", "udpin:127.0.0.1:$port"))
                }
                said.lines.last() shouldContain "cleared the mission list of vehicle 12"
                sim.missionServer.list(MissionType.MISSION).shouldBeEmpty()
            } finally {
                sim.stop()
                dir.toFile().deleteRecursively()
            }
        }
    }

    "for people a transfer's progress shows only once its total is known: a download waits for the vehicle's count" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 14, autopilot = Autopilot.PX4, gcs = "udpout://127.0.0.1:$port"))
            val dir = Files.createTempDirectory("pod-mission-progress")
            try {
                sim.start(this)
                val upload = dir.resolve("plan.waypoints").also { WplFile.write(it, withHome(waypoints(25).map { w -> w.copy(current = false) })) }
                val connect = listOf("--connect", "udpin:127.0.0.1:$port")
                val up = Lines()
                withContext(Dispatchers.IO) { Pod(up).parse(listOf("mission", "upload", upload.toString()) + connect) }
                // (A "waiting for a vehicle" line may come first on a slow machine.)
                up.lines.first { !it.startsWith("waiting") } shouldBe "uploading 0/25 items (0%)"
                up.lines.last() shouldBe "uploaded 25 mission items to vehicle 14"

                val down = Lines()
                withContext(Dispatchers.IO) { Pod(down).parse(listOf("mission", "download", dir.resolve("back.waypoints").toString()) + connect) }
                val progress = down.lines.filter { it.startsWith("downloading") }
                progress.none { "/0" in it } shouldBe true // no bar, full or empty, before MISSION_COUNT
                progress.first() shouldBe "downloading 0/25 items (0%)"
                progress.last() shouldBe "downloading 25/25 items (100%)"
                progress.size shouldBe progress.toSet().size
                down.lines.joinToString("\n") shouldNotContain "\u001b"
            } finally {
                sim.stop()
                dir.toFile().deleteRecursively()
            }
        }
    }

    "a malformed WPL file fails with its line number and exit code 2 (bad input), before any vehicle is asked" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 13, gcs = "udpout://127.0.0.1:$port"))
            val file = Files.createTempFile("pod-bad", ".waypoints")
            try {
                sim.start(this)
                file.writeText("QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t41.1\t-8.6\t100\t1\n1\t0\t3\t16\t0\t0\t0\t0\tnorth\t-8.6\t30\t1\n")
                val error = shouldThrow<CliktError> {
                    withContext(Dispatchers.IO) { Pod(Lines()).parse(listOf("mission", "upload", file.toString(), "--connect", "udpin:127.0.0.1:$port")) }
                }
                error.statusCode shouldBe 2
                error.message!! shouldContain "line 3"
                sim.missionServer.list(MissionType.MISSION).shouldBeEmpty()
            } finally {
                sim.stop()
                Files.deleteIfExists(file)
            }
        }
    }

    "a WPL waypoint below home and kilometres away uploads with a warning for each, measured from the vehicle's home" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 18, gcs = "udpout://127.0.0.1:$port"))
            val dir = Files.createTempDirectory("pod-mission-warn")
            try {
                sim.start(this)
                val home = SimVehicleConfig.DEFAULT_HOME
                fun at(seq: Int, north: Double, alt: Float, frame: Int = 3) = home.offset(north.m, 0.m).let {
                    MissionItem(seq, frame, 16, x = Math.round(it.latitude * 1e7).toInt(), y = Math.round(it.longitude * 1e7).toInt(), z = alt)
                }
                val items = listOf(at(0, 0.0, home.altitude.meters.toFloat(), frame = 0), at(1, 100.0, 20f), at(2, 7_700.0, -20f))
                val upload = dir.resolve("far.waypoints").also { WplFile.write(it, items) }
                val out = Captured()
                withContext(Dispatchers.IO) { Pod(out).parse(listOf("mission", "upload", upload.toString(), "--connect", "udpin:127.0.0.1:$port", "--json")) }
                out.events.filterIsInstance<Event.Warning>().map { it.message.substringAfter(": ") } shouldBe listOf(
                    "item 2 is 20 m below home", "item 2 is 7.7 km from home", "item 2 is 7.6 km from item 1 before it",
                )
                out.events.last().shouldBeInstanceOf<Event.Done>().items shouldBe 3
            } finally {
                sim.stop()
                dir.toFile().deleteRecursively()
            }
        }
    }

    "no vehicle on the link is a clear error" {
        val error = shouldThrow<CliktError> {
            withContext(Dispatchers.IO) { Pod(Lines()).parse(listOf("mission", "clear", "--connect", "udpin:127.0.0.1:${freePort()}", "--wait", "1s")) }
        }
        error.statusCode shouldBe 1
        error.message!! shouldContain "no vehicle heard within 1.0 s"
    }
})
