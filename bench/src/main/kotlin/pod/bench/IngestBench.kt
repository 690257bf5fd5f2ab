package pod.bench

import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.options.split
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.runBlocking
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.addJsonObject
import kotlinx.serialization.json.buildJsonArray
import kotlinx.serialization.json.put
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import java.io.File
import java.lang.management.ManagementFactory
import java.net.InetSocketAddress
import java.net.StandardSocketOptions
import java.nio.ByteBuffer
import java.nio.channels.ClosedChannelException
import java.nio.channels.DatagramChannel
import java.util.Locale
import java.util.concurrent.locks.LockSupport
import kotlin.concurrent.thread
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * End-to-end UDP ingest on loopback: one sender thread pushes pre-encoded GLOBAL_POSITION_INT
 * datagrams from [SYSTEMS] vehicles (which first announced themselves with HEARTBEATs) at a few
 * offered rates, to a Pod [GroundStation] and, for reference, to a bare NIO receiver that only
 * counts. Reports for each: offered rate, delivered rate, loss, and receiver CPU per datagram.
 *
 * Usage: `IngestBenchKt [--count N] [--rates 20000,50000,100000,max] [--repeats R]
 * [--send-limit 15s] [--targets POD,NIO] [--thread-cpu true] [--json results.json]`. Every run is bounded by its count and by the send
 * limit, and the whole program ends by itself.
 */
fun main(args: Array<String>) {
    val options = IngestOptions.parse(args)
    println(
        "ingest: ${options.count} datagrams per run, GLOBAL_POSITION_INT from $SYSTEMS systems, loopback, " +
            "rates ${options.loads.joinToString { it.label }}, ${options.repeats} repeat(s), send limit ${options.sendLimit}",
    )
    val results = mutableListOf<IngestResult>()
    // A receiver that fails once (a codec still to be written) is reported and left out of the
    // remaining runs, so that the other's figures still come out.
    val working = options.targets.toMutableSet()
    fun attempt(target: Target, what: String, run: () -> IngestResult): IngestResult? = try {
        run()
    } catch (e: Exception) {
        println("  $what ${target.label}: FAILED, left out from now on: $e")
        working -= target
        null
    } catch (e: NotImplementedError) {
        println("  $what ${target.label}: FAILED, left out from now on: $e")
        working -= target
        null
    }
    // Warm-up: the first pass through the receive path runs interpreted and compiles as it goes.
    // It is paced at a rate Pod keeps up with, so that every datagram goes through (and trains
    // the JIT on) the whole path; an unthrottled warm-up would mostly exercise the kernel's drops.
    for (target in options.targets) {
        attempt(target, "warm-up") { runOnce(target, WARMUP_LOAD, minOf(options.count, WARMUP_COUNT), options.sendLimit, false) }
            ?.let { println("  warm-up ${it.describe()} (discarded)") }
    }
    repeat(options.repeats) { round ->
        for (load in options.loads) {
            // Interleaved, so that slow drift of a noisy machine hits both receivers alike.
            for (target in options.targets.filter { it in working }) {
                val result = attempt(target, "round ${round + 1}") { runOnce(target, load, options.count, options.sendLimit, options.threadCpu) } ?: continue
                println("  round ${round + 1}: ${result.describe()}")
                results += result
            }
        }
    }
    if (results.isEmpty()) {
        println("ingest: no results")
        return
    }
    val summary = summarize(results)
    println()
    println(table(summary))
    options.json?.let { file ->
        file.parentFile?.mkdirs()
        file.writeText(toJson(summary))
        println("wrote ${file.path}")
    }
}

/** Simulated vehicles sending at once (system ids 1..3). */
const val SYSTEMS = 3

private const val WARMUP_COUNT = 200_000
private val WARMUP_LOAD = OfferedLoad(40_000)

/** Requested SO_RCVBUF for both receivers: the size Pod's UdpLink asks for (Linux caps it at net.core.rmem_max). */
internal const val RECEIVE_BUFFER_BYTES = 4 shl 20

/** How long a receiver may stay idle after the sender finished before the run is declared over. */
private val SETTLE = 500.milliseconds

/** An offered load: datagrams per second, or as fast as the sender can go when [perSecond] is null. */
data class OfferedLoad(val perSecond: Int?) {
    val label: String get() = perSecond?.let { "%,d/s".format(Locale.ROOT, it) } ?: "unthrottled"

    companion object {
        val UNTHROTTLED = OfferedLoad(null)

        fun parse(text: String): OfferedLoad =
            if (text == "max") UNTHROTTLED else OfferedLoad(text.replace("_", "").toInt().also { require(it > 0) })
    }
}

/** Command line of the ingest harness. */
data class IngestOptions(
    val count: Int = 200_000,
    val loads: List<OfferedLoad> = listOf(20_000, 50_000, 100_000).map { OfferedLoad(it) } + OfferedLoad.UNTHROTTLED,
    val repeats: Int = 3,
    val sendLimit: Duration = 15.seconds,
    val targets: List<Target> = Target.entries,
    /** Print each run's CPU time per JVM thread (where the receive path spends it). */
    val threadCpu: Boolean = false,
    val json: File? = null,
) {
    companion object {
        /** The options [args] give (see [main] for the list). */
        fun parse(args: Array<String>): IngestOptions = IngestCommand().parse(args)
    }
}

/** [IngestOptions] read from the command line. */
private class IngestCommand : BenchCommand<IngestOptions>("IngestBenchKt", "UDP ingest: Pod's receive path against a bare NIO receiver.") {
    private val d = IngestOptions()
    private val count by option("--count", help = "datagrams per run").count(1..Int.MAX_VALUE).default(d.count)
    private val loads by option("--rates", help = "offered loads per second, or max").convert { OfferedLoad.parse(it.trim()) }.split(",").default(d.loads)
    private val repeats by option("--repeats").count(1..Int.MAX_VALUE).default(d.repeats)
    private val sendLimit by option("--send-limit").duration(1.seconds..2.minutes).default(d.sendLimit)
    private val targets by option("--targets").names<Target>().default(d.targets)
    private val threadCpu by option("--thread-cpu").yesNo().default(d.threadCpu)
    private val json by option("--json").file()

    override fun options(): IngestOptions = IngestOptions(count, loads, repeats, sendLimit, targets, threadCpu, json)
}

/** The two receivers compared. */
enum class Target(val label: String) {
    POD("Pod GroundStation"),
    NIO("bare NIO DatagramChannel"),
}

/** One run: what was offered and what came out. */
data class IngestResult(
    val target: Target,
    val load: OfferedLoad,
    val sent: Long,
    val offeredPerSecond: Double,
    val delivered: Long,
    val deliveredPerSecond: Double,
    /** Process CPU spent while receiving, minus the sender's and the poller's own: receive path, GC and JIT. */
    val receiverCpuNanos: Long,
    /** Datagrams the kernel dropped for a full receive buffer during the run (Linux /proc/net/snmp), or -1. */
    val kernelDrops: Long,
    /** Frames Pod itself counted as lost from sequence gaps (null for the NIO receiver). */
    val podGapLoss: Long?,
) {
    val lossPercent: Double get() = if (sent == 0L) 0.0 else 100.0 * (sent - delivered) / sent
    val cpuMicrosPerDatagram: Double get() = if (delivered == 0L) Double.NaN else receiverCpuNanos / 1000.0 / delivered

    fun describe(): String = String.format(
        Locale.ROOT,
        "%-24s %-12s sent %,9d at %,9.0f/s  delivered %,9d at %,9.0f/s  loss %5.1f%%  cpu %.2f µs/dgram  kernel drops %,d%s",
        target.label, load.label, sent, offeredPerSecond, delivered, deliveredPerSecond, lossPercent,
        cpuMicrosPerDatagram, kernelDrops, podGapLoss?.let { ", Pod's gap count $it" } ?: "",
    )
}

/**
 * Sends [count] datagrams at [load] to a fresh receiver of [target], and measures until everything
 * arrived or the receiver stayed idle for [SETTLE] after the last send.
 */
fun runOnce(target: Target, load: OfferedLoad, count: Int, sendLimit: Duration, threadCpu: Boolean): IngestResult {
    val receiver: Receiver = when (target) {
        Target.POD -> PodReceiver.open()
        Target.NIO -> NioReceiver()
    }
    receiver.use {
        Sender(receiver.address).use { sender ->
            receiver.announce(sender)
            val threads = ManagementFactory.getThreadMXBean()
            val os = ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean
            val drops0 = KernelUdpCounters.receiveBufferErrors()
            val threadsBefore = if (threadCpu) ThreadCpu.snapshot() else emptyMap()
            val cpu0 = os.processCpuTime
            val poller0 = threads.currentThreadCpuTime
            val start = System.nanoTime()

            val outcome = SendOutcome()
            val sending = thread(name = "ingest-sender") {
                sender.sendPositions(count, load, start, start + sendLimit.inWholeNanoseconds, outcome)
            }

            // Poll the receiver's count every millisecond and note when it last moved: the delivered
            // rate is what arrived over the time it took to arrive.
            var seen = 0L
            var lastChange = start
            val hardStop = start + (sendLimit + 10.seconds).inWholeNanoseconds
            while (true) {
                LockSupport.parkNanos(1_000_000)
                val now = System.nanoTime()
                val processed = receiver.processed()
                if (processed != seen) {
                    seen = processed
                    lastChange = now
                }
                if (outcome.done) {
                    if (seen >= outcome.sent) break
                    if (now - maxOf(lastChange, outcome.endNanos) > SETTLE.inWholeNanoseconds) break
                }
                if (now > hardStop) break
            }
            sending.join(SETTLE.inWholeMilliseconds)
            val receiverCpu = os.processCpuTime - cpu0 - outcome.cpuNanos - (threads.currentThreadCpuTime - poller0)
            val drops1 = KernelUdpCounters.receiveBufferErrors()
            if (threadCpu) ThreadCpu.print(threadsBefore, ThreadCpu.snapshot(), "${target.label} at ${load.label}")
            val sendSeconds = (outcome.endNanos - start) / 1e9
            val receiveSeconds = (lastChange - start) / 1e9
            return IngestResult(
                target = target,
                load = load,
                sent = outcome.sent,
                offeredPerSecond = if (sendSeconds > 0) outcome.sent / sendSeconds else 0.0,
                delivered = seen,
                deliveredPerSecond = if (receiveSeconds > 0) seen / receiveSeconds else 0.0,
                receiverCpuNanos = receiverCpu,
                kernelDrops = if (drops0 < 0 || drops1 < 0) -1 else drops1 - drops0,
                podGapLoss = receiver.gapLoss(),
            )
        }
    }
}

/** Median of each (target, load) over the repeats, ordered as offered. */
data class IngestSummary(val target: Target, val load: OfferedLoad, val runs: List<IngestResult>) {
    private fun median(values: List<Double>): Double = values.sorted().let { s ->
        if (s.size % 2 == 1) s[s.size / 2] else (s[s.size / 2 - 1] + s[s.size / 2]) / 2
    }

    val offered: Double get() = median(runs.map { it.offeredPerSecond })
    val delivered: Double get() = median(runs.map { it.deliveredPerSecond })
    val loss: Double get() = median(runs.map { it.lossPercent })
    val lossRange: ClosedFloatingPointRange<Double> get() = runs.minOf { it.lossPercent }..runs.maxOf { it.lossPercent }
    val cpuMicros: Double get() = median(runs.map { it.cpuMicrosPerDatagram })
}

private fun summarize(results: List<IngestResult>): List<IngestSummary> =
    results.groupBy { it.load to it.target }.map { (key, runs) -> IngestSummary(key.second, key.first, runs) }

private fun table(summary: List<IngestSummary>): String = buildString {
    appendLine("Ingest (median of ${summary.first().runs.size} run(s); loss range in brackets)")
    appendLine("| offered load | target | offered (dgram/s) | delivered (dgram/s) | loss | receiver CPU (µs/dgram) |")
    appendLine("|---|---|---:|---:|---:|---:|")
    for (s in summary) {
        appendLine(
            String.format(
                Locale.ROOT, "| %s | %s | %,.0f | %,.0f | %.1f %% [%.1f–%.1f] | %.2f |",
                s.load.label, s.target.label, s.offered, s.delivered, s.loss, s.lossRange.start, s.lossRange.endInclusive, s.cpuMicros,
            ),
        )
    }
}

private fun toJson(summary: List<IngestSummary>): String = JsonText.pretty.encodeToString(
    JsonArray.serializer(),
    buildJsonArray {
        for (s in summary) {
            addJsonObject {
                put("target", s.target.name)
                put("load", s.load.label)
                put("offered", JsonText.num(s.offered))
                put("delivered", JsonText.num(s.delivered))
                put("lossPercent", JsonText.num(s.loss))
                put("lossMin", JsonText.num(s.lossRange.start))
                put("lossMax", JsonText.num(s.lossRange.endInclusive))
                put("cpuMicrosPerDatagram", JsonText.num(s.cpuMicros))
                put("runs", s.runs.size)
            }
        }
    },
) + "\n"
