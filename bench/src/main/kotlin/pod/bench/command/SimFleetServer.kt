package pod.bench.command

import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import pod.bench.BenchCommand
import pod.bench.duration
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import kotlinx.serialization.json.JsonObjectBuilder
import kotlinx.serialization.json.buildJsonObject
import kotlinx.serialization.json.put
import pod.bench.JsonText
import pod.bench.RelayedVehicle
import pod.bench.percentile
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.link.MavlinkLink
import pod.sim.SimFleet
import pod.sim.SimVehicleConfig
import kotlin.concurrent.thread
import kotlin.system.exitProcess
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.seconds

/**
 * The simulated fleets of the command benchmark, in a JVM of their own so that either ground
 * station (Pod in the harness's JVM, pymavlink in Python) shares the machine with the same
 * separate vehicle process. Driven over stdin, one command a line; answers on stdout, one flat
 * JSON object a line:
 *
 * - on start it warms its own code path (its vehicles answering [WARM_UP_ROUNDS] rounds of
 *   commands from an in-process ground station), then prints `{"event": "ready"}`;
 * - `start N LOSS_PERCENT SEED PORT`: N vehicles (system ids 1..N) sending to loopback PORT,
 *   each behind its own seeded relay when LOSS_PERCENT > 0; prints `{"event": "started"}`;
 * - `cpu`: prints `{"event": "cpu", "seconds": …}`, the CPU time this process has used so far;
 * - `stop`: stops them; prints `{"event": "stopped", "droppedToGcs": …, "droppedToVehicle": …}`;
 * - end of stdin, or `--limit` (default 2 h) after start: exits.
 *
 * Usage: `SimFleetServerKt [--limit 7200s]`.
 */
fun main(args: Array<String>) {
    val limit = ServerCommand().parse(args)
    thread(isDaemon = true, name = "fleet-limit") {
        Thread.sleep(limit.inWholeMilliseconds)
        System.err.println("fleet server: limit $limit reached, exiting")
        exitProcess(2)
    }
    val input = System.`in`.bufferedReader()
    runBlocking(Dispatchers.Default) {
        val warm = warmUp()
        emit("ready") { put("warmUpSeconds", JsonText.num(warm.first)); put("warmUpMedianMs", JsonText.num(warm.second)) }
        var fleet: RunningFleet? = null
        while (true) {
            // Blocking read on this coroutine's thread is fine: nothing else needs it between commands.
            val line = input.readLine() ?: break
            val words = line.trim().split(Regex("\\s+"))
            try {
                when (words[0]) {
                    "start" -> {
                        check(fleet == null) { "a fleet is already running" }
                        val (n, loss, seed, port) = words.drop(1).map { it.toLong() }
                        fleet = RunningFleet.start(this, n.toInt(), loss / 100.0, seed, port.toInt())
                        emit("started") { put("vehicles", n) }
                    }
                    "stop" -> {
                        val f = fleet
                        fleet = null
                        f?.stop()
                        emit("stopped") { put("droppedToGcs", f?.droppedToGcs ?: 0); put("droppedToVehicle", f?.droppedToVehicle ?: 0) }
                    }
                    "cpu" -> emit("cpu") { put("seconds", processCpuSeconds()) }
                    "" -> {}
                    else -> error("unknown command '${words[0]}'")
                }
            } catch (e: Exception) {
                emit("error") { put("message", e.toString()) }
            }
        }
        fleet?.stop()
        coroutineContext.cancelChildren()
    }
    exitProcess(0)
}

/** CPU time this JVM has used so far, all threads (JIT and GC included). */
fun processCpuSeconds(): Double =
    (java.lang.management.ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean).processCpuTime / 1e9

/** Prints one flat JSON object, its kind in "event" first, then what [fields] puts. */
private fun emit(event: String, fields: JsonObjectBuilder.() -> Unit = {}) {
    println(buildJsonObject { put("event", event); fields() })
    System.out.flush()
}

/** Rounds of the fleet process's own warm-up. */
private const val WARM_UP_ROUNDS = 300

/**
 * 10 vehicles answering [WARM_UP_ROUNDS] rounds of 10 concurrent commands from a ground station in
 * this JVM, so that the vehicles' receive and answer path is compiled before anything is measured.
 * Returns the seconds it took and the median latency of the last 100 rounds, in ms.
 */
private suspend fun warmUp(): Pair<Double, Double> = coroutineScope {
    val started = System.nanoTime()
    val gcs = GroundStation.open(MavlinkLink.open("udpin://127.0.0.1:0"), this, GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false))
    val fleet = SimFleet.start(10, this, SimVehicleConfig(systemId = 1, gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
    try {
        val vehicles = withTimeout(30.seconds) { gcs.vehicles.first { it.size >= 10 } }.values.sortedBy { it.systemId }
        val late = ArrayList<Double>()
        repeat(WARM_UP_ROUNDS) { r ->
            val round = podRound(vehicles, null, 10.seconds)
            if (r >= WARM_UP_ROUNDS - 100) late += round.latenciesUs
            kotlinx.coroutines.delay(1.milliseconds)
        }
        (System.nanoTime() - started) / 1e9 to percentile(late, 50.0) / 1000
    } finally {
        fleet.stop()
        gcs.close()
        coroutineContext.cancelChildren()
    }
}

/** The vehicles of one case: a plain [SimFleet], or one relayed vehicle per system id. */
private class RunningFleet(private val plain: SimFleet?, private val relayed: List<RelayedVehicle>) {
    val droppedToGcs: Long get() = relayed.sumOf { it.droppedToGcs }
    val droppedToVehicle: Long get() = relayed.sumOf { it.droppedToVehicle }

    fun stop() {
        plain?.stop()
        relayed.forEach { it.close() }
    }

    companion object {
        suspend fun start(scope: CoroutineScope, count: Int, loss: Double, seed: Long, port: Int): RunningFleet {
            val base = SimVehicleConfig(systemId = 1, gcs = "udpout://127.0.0.1:$port")
            if (loss <= 0.0) return RunningFleet(SimFleet.start(count, scope, base), emptyList())
            val started = ArrayList<RelayedVehicle>()
            try {
                for (i in 1..count) started += RelayedVehicle.start(scope, base.copy(systemId = i), loss, seed * 1000 + i, port)
            } catch (e: Throwable) {
                started.forEach { it.close() }
                throw e
            }
            return RunningFleet(null, started)
        }
    }
}

/** The server's time limit from the command line. */
private class ServerCommand : BenchCommand<Duration>("SimFleetServerKt", "Simulated vehicles for the command benchmark, driven over stdin.") {
    private val limit by option("--limit", help = "exit this long after start").duration(1.seconds..24.hours).default(7200.seconds)

    override fun options(): Duration = limit
}
