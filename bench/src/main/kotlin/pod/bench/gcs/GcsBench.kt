package pod.bench.gcs

import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.sync.Semaphore
import kotlinx.coroutines.sync.withPermit
import kotlinx.coroutines.withTimeout
import pod.bench.BenchCommand
import pod.bench.count
import pod.bench.duration
import pod.bench.file
import pod.bench.number
import pod.cli.gcs.GcsFleet
import pod.cli.gcs.GcsServer
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.MessageIds
import java.io.File
import java.util.concurrent.atomic.AtomicInteger
import kotlin.math.cos
import kotlin.math.sin
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * `pod gcs` at fleet scale: [GcsOptions.vehicles] simulated copters (`pod sim` in a JVM of its own,
 * real time) streaming GLOBAL_POSITION_INT at [GcsOptions.rate] Hz to a Pod station in this JVM,
 * all taken off and sent flying outwards so that every position changes; the ground station's
 * server serving them; then headless chromium showing the page for [GcsOptions.window].
 *
 * Measures this process's CPU over a window with no page open and over one with the page open
 * (the difference is the serving), the WebSocket's messages, bytes and batch sizes ([pod.cli.gcs.GcsStats]),
 * and in the browser the frame time (requestAnimationFrame deltas), long tasks and the batches it
 * took in ([GcsPageProbe]).
 *
 * `java -cp … pod.bench.gcs.GcsBenchKt [--vehicles 250] [--rate 10] [--window 60s] [--json out.json]`
 */
fun main(args: Array<String>) {
    val options = GcsBenchCommand().parse(args)
    val result = runBlocking(Dispatchers.Default) { run(options) }
    println(result.markdown())
    options.json?.writeText(result.json() + "\n")
}

data class GcsOptions(val vehicles: Int, val rate: Double, val window: Duration, val json: File?)

private class GcsBenchCommand : BenchCommand<GcsOptions>("GcsBenchKt", "pod gcs serving hundreds of flying vehicles to one page in headless chromium.") {
    private val vehicles by option("--vehicles").count(1..254).default(250)
    private val rate by option("--rate", help = "GLOBAL_POSITION_INT per vehicle per second").number(0.1..50.0).default(10.0)
    private val window by option("--window", help = "each measured window").duration(5.seconds..1.hours).default(60.seconds)
    private val json by option("--json").file()

    override fun options() = GcsOptions(vehicles, rate, window, json)
}

private suspend fun run(options: GcsOptions): GcsResult {
    val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    // The executor's streams, with the position at the benchmark's rate (ArduCopter streams nothing until asked).
    val config = GroundStationConfig(streamRates = GroundStationConfig.DEFAULT_STREAM_RATES + (MessageIds.GLOBAL_POSITION_INT to options.rate))
    val station = GroundStation.open("udpin://127.0.0.1:0", scope, config)
    val sim = SimProcess(options.vehicles, station.link.localPort)
    try {
        withTimeout(3.minutes) { station.vehicles.first { it.size == options.vehicles } }
        val flying = fly(station.vehicles.value.values.toList())
        val fleet = GcsFleet(station, scope, "${options.vehicles} simulated copters", 1.0)
        val server = GcsServer.start(fleet, "127.0.0.1", 0)
        try {
            delay(5.seconds) // the fleet's streams settle at the asked rates
            val idle = CpuWindow.measure(options.window)
            val page = GcsPageProbe(server.url, options.vehicles).use { probe ->
                probe.awaitFleet()
                val stats0 = ServerCounts.of(server.stats)
                val busy = CpuWindow.measure(options.window) { probe.start() }
                val browser = probe.finish()
                PageWindow(busy, ServerCounts.of(server.stats) - stats0, browser)
            }
            return GcsResult(options, flying, station.stats.value.frames, idle, page)
        } finally {
            server.close()
        }
    } finally {
        sim.close()
        scope.cancel()
    }
}

/** Takes every vehicle off and sends it 5 km outwards, each on its own bearing; returns how many fly. */
private suspend fun fly(vehicles: List<MavlinkVehicle>): Int {
    val ok = AtomicInteger()
    val permits = Semaphore(50)
    kotlinx.coroutines.coroutineScope {
        vehicles.forEachIndexed { i, v ->
            launch {
                permits.withPermit {
                    runCatching {
                        v.action.getAirborne(20.m)
                        val here = v.telemetry.position.value!!.location
                        val bearing = 2 * Math.PI * i / vehicles.size
                        val north = 5_000 * cos(bearing)
                        val east = 5_000 * sin(bearing)
                        val target = Location(
                            here.latitude + north / 111_320.0,
                            here.longitude + east / (111_320.0 * cos(Math.toRadians(here.latitude))),
                            here.altitude,
                        )
                        v.action.goto(target)
                        ok.incrementAndGet()
                    }.onFailure { System.err.println("vehicle ${v.systemId}: ${it.message}") }
                }
            }
        }
    }
    return ok.get()
}

/** `pod sim --vehicles N` in a JVM of its own on this classpath, sending to [port]; its output to a temporary file. */
private class SimProcess(vehicles: Int, port: Int) : AutoCloseable {
    private val log = File.createTempFile("gcs-bench-sim-", ".log").apply { deleteOnExit() }
    private val process = ProcessBuilder(
        File(System.getProperty("java.home"), "bin/java").path, "-Xmx1g", "-cp", System.getProperty("java.class.path"),
        "pod.cli.MainKt", "sim", "--vehicles", "$vehicles", "--out", "udpout:127.0.0.1:$port", "--json",
    ).redirectErrorStream(true).redirectOutput(log).start()

    override fun close() {
        process.destroy()
        if (!process.waitFor(10, java.util.concurrent.TimeUnit.SECONDS)) process.destroyForcibly()
    }
}
