package pod.e2e

import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.parse
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.ints.shouldBeGreaterThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.cli.Output
import pod.cli.Pod
import pod.e2e.Python.stop
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.net.DatagramSocket
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration.Companion.seconds

/** What a command printed, line by line, and a flow to await a line as it comes. */
private class Captured : Output {
    val lines = CopyOnWriteArrayList<String>()
    val flow = MutableSharedFlow<String>(replay = 10_000)
    override fun line(text: String) {
        lines += text
        flow.tryEmit(text)
    }
}

private fun String.field(name: String): String? =
    Regex("\"$name\":(\"[^\"]*\"|[^,}]*)").find(this)?.groupValues?.get(1)?.trim('"')

class CliSpec : StringSpec({

    "pod watch sees a vehicle that is not Pod's: pymavlink's heartbeats and positions" {
        coroutineScope {
            val out = Captured()
            val watch = async(Dispatchers.IO) {
                Pod(out).parse(listOf("watch", "--connect", "udpin:127.0.0.1:0", "--json", "--duration", "6s", "--lost-after", "1s"))
            }
            val listening = withTimeout(20.seconds) { out.flow.first { it.contains("\"event\":\"listening\"") } }
            val port = listening.field("port")!!.toInt()
            val peer = Python.start("pymavlink_vehicle.py", port, 42, 3)
            try {
                val found = withTimeout(20.seconds) { out.flow.first { it.contains("\"event\":\"found\"") } }
                found.field("sysid") shouldBe "42"
                found.field("type") shouldBe "FIXED_WING"
                found.field("autopilot") shouldBe "ARDUPILOT"
                val telemetry = withTimeout(10.seconds) {
                    out.flow.first { it.contains("\"event\":\"telemetry\"") && it.field("lat") != "null" }
                }
                telemetry.field("lat")!!.toDouble() shouldBe 41.1234567
                telemetry.field("lon")!!.toDouble() shouldBe -8.54321
                telemetry.field("alt_msl")!!.toDouble() shouldBe 95.5
                telemetry.field("alt_rel")!!.toDouble() shouldBe 12.3
                telemetry.field("heading")!!.toDouble() shouldBe 90.0
                telemetry.field("mode") shouldBe "AUTO"
                telemetry.field("armed") shouldBe "true"
                // The script stops after 3 s; the watcher then marks the vehicle lost.
                withTimeout(10.seconds) { out.flow.first { it.contains("\"event\":\"lost\"") } }.field("sysid") shouldBe "42"
            } finally {
                peer.stop()
            }
            watch.await()
        }
    }

    "pod watch for people, into a pipe: plain table lines with the vehicle's row, events as lines, no escapes" {
        coroutineScope {
            val out = Captured()
            val watch = async(Dispatchers.IO) {
                Pod(out).parse(listOf("watch", "--connect", "udpin:127.0.0.1:0", "--duration", "8s", "--lost-after", "1s"))
            }
            val listening = withTimeout(20.seconds) { out.flow.first { it.startsWith("listening on") } }
            val port = Regex("local port (\\d+)").find(listening)!!.groupValues[1].toInt()
            val sim = SimVehicle(SimVehicleConfig(systemId = 21, gcs = "udpout://127.0.0.1:$port"))
            try {
                sim.start(this)
                withTimeout(10.seconds) { out.flow.first { it == "found vehicle 21: quadrotor on ardupilot" } }
                val row = withTimeout(10.seconds) { out.flow.first { it.trimStart().startsWith("21 ") } }
                row.split(Regex(" +")).filter { it.isNotEmpty() }.take(4) shouldBe listOf("21", "quadrotor", "ardupilot", "connected")
            } finally {
                sim.stop()
            }
            // Durations for people are rounded seconds, not milliseconds.
            withTimeout(10.seconds) { out.flow.first { it.startsWith("LOST vehicle 21") } } shouldContain Regex("silent for \\d+\\.\\d s$")
            watch.await()
            out.lines.filter { "SYSID" in it }.size shouldBeGreaterThanOrEqual 1
            out.lines.joinToString("\n") shouldNotContain "\u001b"
        }
    }

    "pod demo runs Listing 4: two drones survey, the tired pair hands over to charged ones, and a map is written" {
        val out = Captured()
        val map = kotlin.io.path.createTempFile("pod-demo", ".svg")
        Pod(out).parse(listOf("demo", "--json", "--for", "20m", "--time-scale", "40", "--map", map.toString()))
        val picked = out.lines.filter { it.contains("\"event\":\"picked\"") }.map { it.field("vehicles") }
        picked shouldHaveSize 4
        picked.toSet() shouldBe setOf("1", "2", "3", "4")
        out.lines.filter { it.contains("\"event\":\"flying\"") }.map { it.field("vehicle") }.toSet() shouldBe setOf("1", "2", "3", "4")
        out.lines.last().field("event") shouldBe "demo_done"
        out.lines.last().field("ok") shouldBe "true"
        val svg = kotlin.io.path.Path(map.toString()).toFile().readText()
        svg shouldContain "<svg"
        Regex("<polyline").findAll(svg).count() shouldBeGreaterThanOrEqual 8 // planned and flown, 4 vehicles
    }

    "a bad connection string is a clear error with exit code 2" {
        val error = shouldThrow<CliktError> { Pod(Captured()).parse(listOf("watch", "--connect", "udp-in:nowhere")) }
        error.statusCode shouldBe 2
        error.message!! shouldContain "invalid connection string 'udp-in:nowhere'"
    }

    "a port in use is a clear error with exit code 2" {
        DatagramSocket(0, java.net.InetAddress.getByName("127.0.0.1")).use { taken ->
            val error = shouldThrow<CliktError> {
                Pod(Captured()).parse(listOf("watch", "--connect", "udpin:127.0.0.1:${taken.localPort}", "--duration", "1s"))
            }
            error.statusCode shouldBe 2
            error.message!! shouldContain "already in use"
        }
    }

    "an unknown host is a clear error with exit code 2" {
        val error = shouldThrow<CliktError> {
            Pod(Captured()).parse(listOf("watch", "--connect", "udpout:no-such-host.invalid:14550", "--duration", "1s"))
        }
        error.statusCode shouldBe 2
        error.message!! shouldContain "unknown host"
    }
})
