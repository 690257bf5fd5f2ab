package pod.e2e

import com.github.ajalt.clikt.core.parse
import io.kotest.core.spec.style.StringSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.job
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import pod.cli.json.EventJson
import pod.cli.json.RouteSummary
import pod.core.units.m
import pod.mavlink.GroundStation
import pod.mavlink.MessageIds
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.tlog.TlogReader
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.io.File
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * `pod route` as a process of its own between real peers: a simulated copter on one link, a Pod
 * station flying it on a second, and MAVProxy (from the venv) on a third, which sees the vehicle
 * and fetches its parameters through the router while the flight goes on.
 */
class RouteInteropSpec : StringSpec({

    "MAVProxy behind pod route sees the vehicle and fetches its parameters while a Pod station flies it through another output" {
        val dir = tempdir()
        val mavproxyLog = File(dir, "mavproxy.tlog")
        val vehiclePort = freePort()
        val stationPort = freePort()
        val mavproxyPort = freePort()
        coroutineScope {
            // A process's output readers may end with "Stream closed" when it exits: not this test's failure.
            val processes = CoroutineScope(coroutineContext + SupervisorJob(coroutineContext.job) + CoroutineExceptionHandler { _, _ -> })
            val route = processes.startPod(listOf("route", "udpin:127.0.0.1:$vehiclePort", "udpout:127.0.0.1:$stationPort", "udpin:127.0.0.1:$mavproxyPort", "--json", "--every", "2s"))
            val gcs = GroundStation.open("udpin://127.0.0.1:$stationPort", this)
            val sim = SimVehicle(SimVehicleConfig(systemId = 43, gcs = "udpout://127.0.0.1:$vehiclePort", timeScale = 4.0))
            lateinit var mavproxy: Process
            try {
                try {
                    withTimeout(1.minutes) { route.out.first { lines -> lines.count { "\"listening\"" in it } == 3 } }
                    mavproxy = startMavproxyOn(dir, mavproxyPort, mavproxyLog)
                    sim.start(this)
                    val v = Flights.vehicle(gcs, 43)
                    val home = v.telemetry.position.value!!.location
                    Flights.keepArmedOnGround(v)
                    v.action.arm()
                    v.action.takeoff(10.m)
                    val target = home.offset(north = 30.m, east = 0.m, up = 10.m)
                    v.action.goto(target)
                    v.action.awaitArrival(target, within = 1.m, timeout = 2.minutes)
                    // MAVProxy heard the vehicle and its whole parameter list, which only its own PARAM_REQUEST_LIST (to 43/1,
                    // through the router) asks for: Pod's station writes one parameter, whose answer is a single PARAM_VALUE.
                    withTimeout(1.minutes) {
                        while (mavproxyLog.count(43, MessageIds.HEARTBEAT) == 0 || mavproxyLog.count(43, PARAM_VALUE) < 20) delay(200.milliseconds)
                    }
                    sim.state.value.armed shouldBe true
                } finally {
                    runInterruptible(Dispatchers.IO) { mavproxy.destroy(); mavproxy.waitFor(30, TimeUnit.SECONDS) }
                    sim.stop()
                    withContext(NonCancellable) { gcs.closeAndAwait() }
                }
                route.signal("INT")
                route.exitCode(30.seconds) shouldBe 130
                val finals = route.out.value.filter { it.startsWith("{\"event\":\"route\"") }.map { EventJson.decode(it) as RouteSummary }.filter { it.final }
                finals shouldHaveSize 3
                finals[0].received shouldBeGreaterThan 100L // the vehicle's telemetry
                finals[1].forwarded shouldBeGreaterThan 100L // to the Pod station
                finals[2].forwarded shouldBeGreaterThan 100L // to MAVProxy
                finals[2].received shouldBeGreaterThan 0L // MAVProxy's heartbeats and its parameter requests
            } finally {
                // Whatever failed above, the router must not outlive the test, nor its output readers keep this scope open.
                route.process.destroyForcibly()
                processes.cancel()
            }
        }
    }

    "pod route prints a line per link and refuses one link, or the same link twice, with exit code 2" {
        val one = Captured()
        pod.cli.run(listOf("route", "udpin:127.0.0.1:${freePort()}"), one, Captured()) shouldBe 2
        val twice = Captured()
        val port = freePort()
        pod.cli.run(listOf("route", "udpin:127.0.0.1:$port", "udpin://127.0.0.1:$port"), Captured(), twice) shouldBe 2
        twice.lines.single() shouldContain "the same link is given twice"
        val out = Captured()
        withContext(Dispatchers.IO) {
            pod.cli.Pod(out).parse(listOf("route", "udpin:127.0.0.1:${freePort()}", "udpout:127.0.0.1:${freePort()}", "--duration", "1s", "--every", "10s"))
        }
        out.lines.filter { it.startsWith("routing ") } shouldHaveSize 2
        out.lines.filter { it.startsWith("route total ") } shouldHaveSize 2
        out.lines.last() shouldContain "0 frames in, 0 forwarded out"
    }
})

private const val PARAM_VALUE = 22

/** How many frames of [messageId] from [systemId] this tlog (written as it goes) holds. */
private fun File.count(systemId: Int, messageId: Int): Int {
    if (!isFile) return 0
    var found = 0
    val decoder = FrameDecoder()
    runCatching { TlogReader.open(toPath()).use { r -> r.readAll() } }.getOrDefault(emptyList()).forEach { record ->
        decoder.feed(record.frame) { if (it.systemId == systemId && it.messageId == messageId) found++ }
    }
    return found
}

/** MAVProxy connecting to [port] (`udpout`, as to a router's listening port), logging to [tlog]; no parameter download over MAVFTP, which the simulator does not serve. */
private fun startMavproxyOn(dir: File, port: Int, tlog: File): Process {
    val script = File(File(Python.executable).parentFile, "mavproxy.py")
    check(script.isFile) { "no $script: run tools/python-peers.sh (it installs MAVProxy into .venv)" }
    return ProcessBuilder(
        listOf(
            Python.executable, script.path, "--master=udpout:127.0.0.1:$port", "--logfile=${tlog.path}", "--state-basedir=${dir.path}",
            "--daemon", "--non-interactive", "--cmd=set flushlogs 1; set param_ftp 0",
        ),
    ).directory(dir).redirectErrorStream(true).redirectOutput(File(dir, "mavproxy.out")).start()
}
