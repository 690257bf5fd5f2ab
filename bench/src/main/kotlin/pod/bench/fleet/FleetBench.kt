package pod.bench.fleet

import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import pod.bench.BenchCommand
import pod.bench.count
import pod.bench.duration
import pod.bench.file
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeoutOrNull
import pod.bench.command.BENCH_COMMAND
import pod.bench.percentile
import pod.mavlink.FleetEvent
import java.io.File
import java.lang.management.ManagementFactory
import java.util.concurrent.ConcurrentLinkedQueue
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * Fleet scale: [Options.links] Pod [pod.mavlink.GroundStation]s (in this JVM, one `udpin` link each, default
 * lostAfter 3 s) hearing [Options.vehicles] vehicles between them (system ids 1..vehicles/links on
 * each link), simulated by [Options.senders] child JVMs ([FleetSender]: 1 Hz HEARTBEAT, 10 Hz
 * GLOBAL_POSITION_INT, 5 Hz ATTITUDE each, a COMMAND_ACK for every COMMAND_LONG), while it sends a
 * command to the next vehicle in turn, over all links, every [Options.commandEvery]. Reports this
 * process's CPU as a share of one core, its threads, the command round trips (p50/p90/p99/max),
 * failures, and every vehicle marked lost (each one false: the senders never stop).
 *
 * `java -cp … pod.bench.fleet.FleetBenchKt [--vehicles 250] [--links 1] [--senders 3] [--duration 10m]
 * [--warmup 30s] [--command-every 50ms] [--json out.json]`
 */
fun main(args: Array<String>) {
    val options = FleetBenchCommand().parse(args)
    val result = runBlocking(Dispatchers.Default) { run(options) }
    println(result.markdown())
    options.json?.writeText(result.json() + "\n")
}

data class Options(
    val vehicles: Int,
    val links: Int,
    val senders: Int,
    val duration: Duration,
    val warmup: Duration,
    val commandEvery: Duration,
    val json: File?,
)

/** [Options] read from the command line. */
private class FleetBenchCommand : BenchCommand<Options>("FleetBenchKt", "Fleet scale: one ground station hearing hundreds of lean vehicles.") {
    private val vehicles by option("--vehicles", help = "in all, at most 255 per link").count(1..255 * 16).default(250)
    private val links by option("--links", help = "ground stations, one udpin link each, in this JVM").count(1..16).default(1)
    private val senders by option("--senders", help = "sender JVMs the vehicles are spread over (at least one per link)").count(1..64).default(3)
    private val duration by option("--duration", help = "measured time").duration(1.seconds..24.hours).default(10.minutes)
    private val warmup by option("--warmup").duration(Duration.ZERO..1.hours).default(30.seconds)
    private val commandEvery by option("--command-every").duration(1.milliseconds..1.minutes).default(50.milliseconds)
    private val json by option("--json").file()

    override fun options(): Options {
        require(vehicles <= 255 * links) { "--vehicles $vehicles: at most 255 per link, so at most ${255 * links} on $links links" }
        return Options(vehicles, links, maxOf(senders, links), duration, warmup, commandEvery, json)
    }
}

data class FleetResult(
    val options: Options,
    val foundIn: Duration,
    val cpuShareOfCore: Double,
    val sendersCpuShare: Double,
    val datagramsPerSecond: Double,
    val latenciesMs: List<Double>,
    val failed: Int,
    val falselyLost: Int,
    val threads: Int,
    val loadBefore: String,
    val loadAfter: String,
) {
    private fun p(q: Double) = percentile(latenciesMs, q)

    fun markdown(): String = buildString {
        appendLine("| vehicles | links | measured | station CPU (% of one core) | threads | datagrams/s in | commands | median ms | p90 ms | p99 ms | max ms | failed | falsely lost | load before → after |")
        appendLine("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
        append(
            "| %d | %d | %s | %.1f | %d | %,.0f | %d | %.3f | %.3f | %.3f | %.3f | %d | %d | %s → %s |".format(
                options.vehicles, options.links, options.duration, cpuShareOfCore * 100, threads, datagramsPerSecond, latenciesMs.size,
                p(50.0), p(90.0), p(99.0), latenciesMs.maxOrNull() ?: Double.NaN, failed, falselyLost, loadBefore, loadAfter,
            ),
        )
        append("\n(senders' JVMs: %.1f %% of one core together; vehicles found in %s)".format(sendersCpuShare * 100, foundIn))
    }

    fun json(): String =
        """{"vehicles":${options.vehicles},"links":${options.links},"threads":$threads,"senders":${options.senders},"durationSeconds":${options.duration.inWholeSeconds},""" +
            """"stationCpuShare":$cpuShareOfCore,"sendersCpuShare":$sendersCpuShare,"datagramsPerSecond":$datagramsPerSecond,""" +
            """"commands":${latenciesMs.size},"p50Ms":${p(50.0)},"p90Ms":${p(90.0)},"p99Ms":${p(99.0)},"maxMs":${latenciesMs.maxOrNull()},""" +
            """"failed":$failed,"falselyLost":$falselyLost,"loadBefore":"$loadBefore","loadAfter":"$loadAfter"}"""
}

private fun loadAverage(): String = File("/proc/loadavg").readText().split(" ").take(3).joinToString(" ")

private suspend fun kotlinx.coroutines.CoroutineScope.run(options: Options): FleetResult {
    val loadBefore = loadAverage()
    val fleet = FleetStations.open(this, options)
    val lost = AtomicInteger()
    val watchers = fleet.stations.map { station -> launch { station.events.collect { if (it is FleetEvent.Lost) lost.incrementAndGet() } } }
    try {
        val started = TimeSource.Monotonic.markNow()
        withTimeoutOrNull(2.minutes) { fleet.awaitVehicles() }
            ?: error("only ${fleet.found()} of ${options.vehicles} vehicles found within 2 minutes")
        val foundIn = started.elapsedNow()
        System.err.println("fleet: ${options.vehicles} vehicles on ${options.links} links found in $foundIn; warming up for ${options.warmup}")

        val latencies = ConcurrentLinkedQueue<Double>()
        val failed = AtomicInteger()
        val measuring = AtomicBoolean(false)
        val commander = launch {
            // Every vehicle of every link in turn: link by link within each system id.
            val vehicles = fleet.stations.map { it.vehicles.value.values.sortedBy { v -> v.systemId } }
                .let { perLink -> (0 until perLink.maxOf { it.size }).flatMap { i -> perLink.mapNotNull { it.getOrNull(i) } } }
            var next = 0
            while (true) {
                val vehicle = vehicles[next++ % vehicles.size]
                val counted = measuring.get()
                launch {
                    val t0 = System.nanoTime()
                    val reply = try {
                        withTimeoutOrNull(10.seconds) { vehicle.commands.send(BENCH_COMMAND) }
                    } catch (e: CancellationException) {
                        throw e
                    } catch (e: Exception) {
                        null
                    }
                    if (counted) if (reply == null) failed.incrementAndGet() else latencies += (System.nanoTime() - t0) / 1e6
                }
                delay(options.commandEvery)
            }
        }
        delay(options.warmup)

        val os = ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean
        val cpu0 = os.processCpuTime
        val sendersCpu0 = fleet.sendersCpuNanos()
        val frames0 = fleet.frames()
        val lost0 = lost.get()
        val t0 = System.nanoTime()
        measuring.set(true)
        System.err.println("fleet: measuring for ${options.duration} (load ${loadAverage()})")
        delay(options.duration)
        measuring.set(false)
        val wall = (System.nanoTime() - t0).toDouble()
        val cpu = (os.processCpuTime - cpu0) / wall
        val sendersCpu = (fleet.sendersCpuNanos() - sendersCpu0) / wall
        // Stats are published four times a second: the rate is good to that.
        val frames = fleet.frames() - frames0
        val falselyLost = lost.get() - lost0
        val threads = ManagementFactory.getThreadMXBean().threadCount
        commander.cancel()
        delay(1.seconds) // the last commands finish or time out uncounted
        return FleetResult(options, foundIn, cpu, sendersCpu, frames / (wall / 1e9), latencies.toList(), failed.get(), falselyLost, threads, loadBefore, loadAverage())
    } finally {
        watchers.forEach { it.cancel() }
        fleet.close()
    }
}
