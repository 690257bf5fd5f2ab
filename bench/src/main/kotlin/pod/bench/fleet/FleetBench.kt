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
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeoutOrNull
import pod.bench.command.BENCH_COMMAND
import pod.bench.percentile
import pod.mavlink.FleetEvent
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import java.io.File
import java.lang.management.ManagementFactory
import java.util.concurrent.ConcurrentLinkedQueue
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * Fleet scale: one Pod [GroundStation] (in this JVM, default lostAfter 3 s) hearing [Options.vehicles]
 * vehicles simulated by [Options.senders] child JVMs ([FleetSender]: 1 Hz HEARTBEAT, 10 Hz
 * GLOBAL_POSITION_INT, 5 Hz ATTITUDE each, a COMMAND_ACK for every COMMAND_LONG), while it sends a
 * command to the next vehicle in turn every [Options.commandEvery]. Reports this process's CPU as a
 * share of one core, the command round trips (p50/p90/p99/max), failures, and every vehicle marked
 * lost (each one false: the senders never stop).
 *
 * `java -cp … pod.bench.fleet.FleetBenchKt [--vehicles 250] [--senders 3] [--duration 10m]
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
    val senders: Int,
    val duration: Duration,
    val warmup: Duration,
    val commandEvery: Duration,
    val json: File?,
)

/** [Options] read from the command line. */
private class FleetBenchCommand : BenchCommand<Options>("FleetBenchKt", "Fleet scale: one ground station hearing hundreds of lean vehicles.") {
    private val vehicles by option("--vehicles").count(1..255).default(250)
    private val senders by option("--senders", help = "sender JVMs the vehicles are spread over").count(1..64).default(3)
    private val duration by option("--duration", help = "measured time").duration(1.seconds..24.hours).default(10.minutes)
    private val warmup by option("--warmup").duration(Duration.ZERO..1.hours).default(30.seconds)
    private val commandEvery by option("--command-every").duration(1.milliseconds..1.minutes).default(50.milliseconds)
    private val json by option("--json").file()

    override fun options(): Options = Options(vehicles, senders, duration, warmup, commandEvery, json)
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
    val loadBefore: String,
    val loadAfter: String,
) {
    private fun p(q: Double) = percentile(latenciesMs, q)

    fun markdown(): String = buildString {
        appendLine("| vehicles | measured | station CPU (% of one core) | datagrams/s in | commands | median ms | p90 ms | p99 ms | max ms | failed | falsely lost | load before → after |")
        appendLine("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
        append(
            "| %d | %s | %.1f | %,.0f | %d | %.3f | %.3f | %.3f | %.3f | %d | %d | %s → %s |".format(
                options.vehicles, options.duration, cpuShareOfCore * 100, datagramsPerSecond, latenciesMs.size,
                p(50.0), p(90.0), p(99.0), latenciesMs.maxOrNull() ?: Double.NaN, failed, falselyLost, loadBefore, loadAfter,
            ),
        )
        append("\n(senders' JVMs: %.1f %% of one core together; vehicles found in %s)".format(sendersCpuShare * 100, foundIn))
    }

    fun json(): String =
        """{"vehicles":${options.vehicles},"senders":${options.senders},"durationSeconds":${options.duration.inWholeSeconds},""" +
            """"stationCpuShare":$cpuShareOfCore,"sendersCpuShare":$sendersCpuShare,"datagramsPerSecond":$datagramsPerSecond,""" +
            """"commands":${latenciesMs.size},"p50Ms":${p(50.0)},"p90Ms":${p(90.0)},"p99Ms":${p(99.0)},"maxMs":${latenciesMs.maxOrNull()},""" +
            """"failed":$failed,"falselyLost":$falselyLost,"loadBefore":"$loadBefore","loadAfter":"$loadAfter"}"""
}

private fun loadAverage(): String = File("/proc/loadavg").readText().split(" ").take(3).joinToString(" ")

private suspend fun kotlinx.coroutines.CoroutineScope.run(options: Options): FleetResult {
    val loadBefore = loadAverage()
    val station = GroundStation.open(
        "udpin://127.0.0.1:0", this,
        GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false),
    )
    val lost = AtomicInteger()
    val watcher = launch { station.events.collect { if (it is FleetEvent.Lost) lost.incrementAndGet() } }
    val java = File(System.getProperty("java.home"), "bin/java").path
    val per = (options.vehicles + options.senders - 1) / options.senders
    val senders = (0 until options.senders).mapNotNull { i ->
        val first = 1 + i * per
        val count = minOf(per, options.vehicles - i * per)
        if (count <= 0) return@mapNotNull null
        ProcessBuilder(
            java, "-Xms128m", "-Xmx128m", "-XX:+UseSerialGC", "-cp", System.getProperty("java.class.path"),
            "pod.bench.fleet.FleetSenderKt", "--port", station.link.localPort.toString(), "--first", first.toString(), "--count", count.toString(),
        ).redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(ProcessBuilder.Redirect.INHERIT).start()
    }
    try {
        val started = TimeSource.Monotonic.markNow()
        withTimeoutOrNull(2.minutes) { station.vehicles.first { it.size >= options.vehicles } }
            ?: error("only ${station.vehicles.value.size} of ${options.vehicles} vehicles found within 2 minutes")
        val foundIn = started.elapsedNow()
        System.err.println("fleet: ${options.vehicles} vehicles found in $foundIn; warming up for ${options.warmup}")

        val latencies = ConcurrentLinkedQueue<Double>()
        val failed = AtomicInteger()
        val measuring = AtomicBoolean(false)
        val commander = launch {
            val ids = station.vehicles.value.keys.sorted()
            var next = 0
            while (true) {
                val vehicle = station.vehicles.value.getValue(ids[next++ % ids.size])
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
        val sendersCpu0 = senders.sumOf { it.cpuNanos() }
        val frames0 = station.stats.value.frames
        val lost0 = lost.get()
        val t0 = System.nanoTime()
        measuring.set(true)
        System.err.println("fleet: measuring for ${options.duration} (load ${loadAverage()})")
        delay(options.duration)
        measuring.set(false)
        val wall = (System.nanoTime() - t0).toDouble()
        val cpu = (os.processCpuTime - cpu0) / wall
        val sendersCpu = (senders.sumOf { it.cpuNanos() } - sendersCpu0) / wall
        // Stats are published four times a second: the rate is good to that.
        val frames = station.stats.value.frames - frames0
        val falselyLost = lost.get() - lost0
        commander.cancel()
        delay(1.seconds) // the last commands finish or time out uncounted
        return FleetResult(options, foundIn, cpu, sendersCpu, frames / (wall / 1e9), latencies.toList(), failed.get(), falselyLost, loadBefore, loadAverage())
    } finally {
        senders.forEach { it.outputStream.close(); it.destroy() }
        senders.forEach { it.waitFor(5, TimeUnit.SECONDS) }
        watcher.cancel()
        station.closeAndAwait()
    }
}

private fun Process.cpuNanos(): Long = toHandle().info().totalCpuDuration().map { it.toNanos() }.orElse(0L)
