package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.core.units.Location
import pod.core.units.m
import pod.launch.geo.GeoJson
import pod.launch.geo.GeoShape
import pod.launch.geo.MapFeatures
import pod.mavlink.GroundStation
import pod.mavlink.tlog.TlogReader
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.io.File
import java.util.concurrent.TimeUnit
import kotlin.math.roundToInt
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/** MAVProxy from the venv, routing [master] to [outs] and logging every frame to [tlog] (flushed as written); its output goes to [dir]/mavproxy.out. */
private fun startMavproxy(dir: File, master: Int, outs: List<Int>, tlog: File): Process {
    val script = File(File(Python.executable).parentFile, "mavproxy.py")
    check(script.isFile) { "no $script: run tools/python-peers.sh (it installs MAVProxy into .venv)" }
    return ProcessBuilder(
        listOf(Python.executable, script.path, "--master=udpin:127.0.0.1:$master") +
            outs.map { "--out=udpout:127.0.0.1:$it" } +
            // flushlogs: MAVProxy's log writer otherwise leaves its tlog in a file buffer that only its
            // exit flushes, and a SIGTERM can end it with the flight's last seconds unwritten
            // (MAVProxy/mavproxy.py log_writer flushes "if mpstate.settings.flushlogs").
            listOf("--logfile=${tlog.path}", "--state-basedir=${dir.path}", "--daemon", "--non-interactive", "--cmd=set flushlogs 1"),
    ).directory(dir).redirectErrorStream(true).redirectOutput(File(dir, "mavproxy.out")).start()
}

/** `pod watch --json` in a process of its own, so that a real SIGTERM stops it as Ctrl-C would. */
private fun startWatch(port: Int, tlog: File): JsonPeer {
    val java = File(System.getProperty("java.home"), "bin/java").path
    return JsonPeer(
        "pod-watch",
        ProcessBuilder(
            listOf(java, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "pod.cli.MainKt") +
                listOf("watch", "--connect", "udpin:127.0.0.1:$port", "--record", tlog.path, "--json"),
        ).redirectError(ProcessBuilder.Redirect.INHERIT).start(),
    )
}

/** Ends [process] with SIGTERM and returns its exit code (a bound against a hung child, not a timing assertion). */
private fun Process.terminate(): Int {
    destroy()
    if (!waitFor(30, TimeUnit.SECONDS)) {
        destroyForcibly()
        throw AssertionError("$this did not exit within 30 s of SIGTERM")
    }
    return exitValue()
}

/**
 * The replay acceptance against real MAVProxy: a simulated copter flown by a Pod station
 * through MAVProxy (as a field setup routes a vehicle to several ground stations), MAVProxy and a
 * `pod watch --record` both logging; then both logs played with `pod replay`.
 */
class ReplayInteropSpec : StringSpec({

    "pod replay plays MAVProxy's tlog of a routed flight with the same vehicle ending where pymavlink reads it ended; pod watch --record of the same flight replays to the same track" {
        val dir = tempdir()
        val mavproxyLog = File(dir, "mavproxy.tlog")
        val watchLog = File(dir, "watch.tlog")
        val master = freePort()
        val watchPort = freePort()
        lateinit var home: Location
        lateinit var target: Location
        coroutineScope {
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this)
            val watch = startWatch(watchPort, watchLog)
            // Listening before the vehicle starts, so the recording holds the whole flight.
            withTimeout(1.minutes) { watch.await("listening") }
            val mavproxy = startMavproxy(dir, master, listOf(gcs.link.localPort, watchPort), mavproxyLog)
            val sim = SimVehicle(SimVehicleConfig(systemId = 41, gcs = "udpout://127.0.0.1:$master", timeScale = 4.0))
            try {
                sim.start(this)
                val v = Flights.vehicle(gcs, 41)
                home = v.telemetry.position.value!!.location
                Flights.keepArmedOnGround(v)
                v.action.arm()
                v.action.takeoff(10.m)
                target = home.offset(north = 40.m, east = 0.m, up = 10.m)
                v.action.goto(target)
                v.action.awaitArrival(target, within = 1.m, timeout = 2.minutes)
                // Stopped over the target: what both logs end with.
                withTimeout(1.minutes) { sim.state.first { it.groundSpeed.metersPerSecond < 0.05 && kotlin.math.abs(it.climbRate.metersPerSecond) < 0.05 } }
                withTimeout(10.seconds) { watch.await("found") { it["sysid"] == "41" } }
            } finally {
                runInterruptible(Dispatchers.IO) { mavproxy.terminate() }
                val watchExit = runInterruptible(Dispatchers.IO) { watch.process.terminate() }
                sim.stop()
                withContext(NonCancellable) { gcs.closeAndAwait() }
                // SIGTERM to a recording watch closes the tlog after a whole record, as Ctrl-C does.
                watchExit shouldBe 130
            }
        }

        // pymavlink's reading of MAVProxy's log: where vehicle 41 last was.
        val python = Python.startJson("tlog_read.py", mavproxyLog.path)
        val positions = try {
            withTimeout(60.seconds) { python.await("end") }
            python.events.replayCache.filter { it["event"] == "item" && it["type"] == "GLOBAL_POSITION_INT" && it["sys"] == "41" }
        } finally {
            python.stop()
        }
        val last = positions.last()

        val replay = pod("replay", mavproxyLog.path, "--speed", "20", "--json", within = 2.minutes)
        replay.code shouldBe 0
        val events = replay.afterVersion.map(EventJson::decode)
        events.first() shouldBe Event.Replaying(mavproxyLog.path, 20.0)
        // MAVProxy's and Pod's station heartbeats are in the log too: neither is a vehicle.
        events.filterIsInstance<Event.Found>().map { it.sysid } shouldBe listOf(41)
        val done = events.last().shouldBeInstanceOf<Event.ReplayDone>()
        done.error shouldBe null
        done.records shouldBe TlogReader.open(mavproxyLog.toPath()).use { it.readAll().size.toLong() }
        val end = events.filterIsInstance<Event.Telemetry>().last { it.sysid == 41 }
        end.connected shouldBe true
        (end.lat!! * 1e7).roundToInt() shouldBe last.getValue("lat").toInt()
        (end.lon!! * 1e7).roundToInt() shouldBe last.getValue("lon").toInt()
        val ended = Location(end.lat!!, end.lon!!, end.altMsl!!.m)
        ended.distanceTo(target).meters shouldBeLessThan 1.5
        ended.copy(altitude = home.altitude).distanceTo(home).meters shouldBeGreaterThan 38.0

        // The watch's own recording, replayed onto a map: the track it flew, the same as pod map draws.
        val replayed = File(dir, "replay.geojson").path
        val mapped = File(dir, "map.geojson").path
        pod("replay", watchLog.path, "--speed", "20", "--map", replayed, within = 2.minutes).let {
            it.code shouldBe 0
            it.out.last() shouldStartWith "replayed "
        }
        pod("map", watchLog.path, "--out", mapped).code shouldBe 0
        val features = GeoJson.read(File(replayed).readText())
        features shouldBe GeoJson.read(File(mapped).readText())
        val track = (features.single { it.properties["kind"] == MapFeatures.TRACK && it.properties["vehicle"] == 41L }.shape as GeoShape.Line).points
        track.last().distanceTo(target).meters shouldBeLessThan 1.5
        track.maxOf { it.copy(altitude = home.altitude).distanceTo(home).meters } shouldBeGreaterThan 38.0
        track.first().copy(altitude = home.altitude).distanceTo(home).meters shouldBeLessThan 1.0
    }
})
