package pod.e2e

import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.parse
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.collections.shouldContainInOrder
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.ints.shouldBeGreaterThanOrEqual
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.take
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.withTimeout
import pod.cli.Pod
import pod.cli.json.Event
import pod.e2e.Python.stop
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.net.DatagramSocket
import kotlin.concurrent.thread
import kotlin.time.Duration.Companion.seconds

class CliSpec : StringSpec({

    "pod watch sees a vehicle that is not Pod's: pymavlink's heartbeats and positions" {
        coroutineScope {
            val out = Captured()
            val watch = async(Dispatchers.IO) {
                Pod(out).parse(listOf("watch", "--connect", "udpin:127.0.0.1:0", "--json", "--duration", "6s", "--lost-after", "1s"))
            }
            val listening = withTimeout(20.seconds) { out.eventsOf<Event.Listening>().first() }
            val peer = Python.start("pymavlink_vehicle.py", listening.port, 42, 3)
            try {
                val found = withTimeout(20.seconds) { out.eventsOf<Event.Found>().first() }
                found shouldBe Event.Found(sysid = 42, compid = 1, type = "FIXED_WING", autopilot = "ARDUPILOT")
                val telemetry = withTimeout(10.seconds) { out.eventsOf<Event.Telemetry>().first { it.lat != null } }
                telemetry.sysid shouldBe 42
                telemetry.lat shouldBe 41.1234567
                telemetry.lon shouldBe -8.54321
                telemetry.altMsl shouldBe 95.5
                telemetry.altRel shouldBe 12.3
                telemetry.heading shouldBe 90.0
                telemetry.mode shouldBe "AUTO"
                telemetry.armed shouldBe true
                // The script stops after 3 s; the watcher then marks the vehicle lost.
                withTimeout(10.seconds) { out.eventsOf<Event.Lost>().first() }.sysid shouldBe 42
            } finally {
                peer.stop()
            }
            watch.await()
            // Every line the watcher printed is one of the model's events.
            out.events.map { it::class }.toSet() shouldContainAll setOf(Event.Listening::class, Event.Found::class, Event.Telemetry::class, Event.Lost::class)
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

    "pod demo runs Listing 4 (two drones survey, the tired pair hands over to charged ones) beside a mission queue fed as it flies, and a map is written" {
        val out = Captured()
        val map = kotlin.io.path.createTempFile("pod-demo", ".svg")
        Pod(out).parse(listOf("demo", "--json", "--for", "20m", "--time-scale", "40", "--map", map.toString()))
        val events = out.events
        val picked = events.filterIsInstance<Event.Picked>().map { it.vehicles }
        picked shouldHaveSize 5
        picked.flatten().sorted() shouldBe listOf(1, 2, 3, 4, 5)
        events.filterIsInstance<Event.Flying>().map { it.vehicle }.toSet() shouldBe setOf(1, 2, 3, 4, 5)
        val said = events.filterIsInstance<Event.Message>().map { it.text }
        said.filter { it.startsWith("queue: ") }.map { it.substringBefore(";") } shouldContainInOrder listOf(
            "queue: appended three gotos", "queue: prepended a counter-clockwise circle for 60 s",
            "queue: replaced the current goto with a segment", "queue: replaced everything with a five-point path", "queue: next() skipped the rest of the path",
        )
        events.filterIsInstance<Event.TaskDone>().map { it.task } shouldContain "queue"
        val missions = events.filterIsInstance<Event.Mission>()
        missions.map { it.what }.toSet() shouldContainAll setOf("uploaded", "started")
        missions.filter { it.what == "uploaded" }.forEach { (it.steps ?: 0) shouldBeGreaterThan 0 }
        events.last() shouldBe Event.DemoDone(ok = true, error = null, map = map.toString())
        val svg = kotlin.io.path.Path(map.toString()).toFile().readText()
        svg shouldContain "<svg"
        Regex("<polyline").findAll(svg).count() shouldBeGreaterThanOrEqual 10 // planned and flown, 5 vehicles
    }

    "pod demo cut short while the queue tour still flies ends cleanly: Listing 4 brings home only the drones it took" {
        val out = Captured()
        val map = kotlin.io.path.createTempFile("pod-demo-short", ".svg")
        Pod(out).parse(listOf("demo", "--json", "--for", "5m", "--time-scale", "60", "--map", map.toString()))
        out.events.last() shouldBe Event.DemoDone(ok = true, error = null, map = map.toString())
    }

    "pod sim --json announces each vehicle it started with a started event" {
        val out = Captured()
        val port = freePort()
        // `pod sim` runs until interrupted; interrupting its thread cancels its runBlocking.
        val sim = thread(name = "pod-sim") {
            runCatching { Pod(out).parse(listOf("sim", "--vehicles", "2", "--sysid", "20", "--out", "udpout:127.0.0.1:$port", "--json")) }
        }
        try {
            val started = withTimeout(20.seconds) { out.eventsOf<Event.Started>().take(2).toList() }
            started.map { it.sysid } shouldBe listOf(20, 21)
            for (e in started) {
                (e.type to e.autopilot) shouldBe ("QUADROTOR" to "ARDUPILOT")
                e.out shouldBe "udpout://127.0.0.1:$port"
                e.localPort.shouldNotBeNull()
            }
            out.events shouldHaveSize 2
        } finally {
            sim.interrupt()
            sim.join(10_000)
        }
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
