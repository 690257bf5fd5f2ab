package pod.bench.fleet

import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import pod.bench.BenchCommand
import pod.bench.count
import pod.bench.duration
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.route.MavlinkRouter
import pod.sim.SimFleet
import pod.sim.SimVehicleConfig
import java.io.File
import java.lang.management.ManagementFactory
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * Threads of a process with many links: a [SimFleet] of `--vehicles` simulated vehicles (one UDP
 * link each) sending to a ground station in the same JVM, then a [MavlinkRouter] between
 * `--route-links` UDP links. For each, the JVM's live threads before and while running, how many
 * of them are UDP receive threads, and the process's CPU over `--window` (the fleet talking, the
 * router idle). Run it against the jars of two worktrees to pair before and after.
 *
 * `java -cp … pod.bench.fleet.LinkThreadsKt [--vehicles 250] [--route-links 50] [--window 10s]`
 */
fun main(args: Array<String>) {
    val options = LinkThreadsCommand().parse(args)
    runBlocking(Dispatchers.Default) {
        println("| process | live threads before | live threads running | of them UDP receive threads | CPU over ${options.window} (% of one core) | load |")
        println("|---|---:|---:|---:|---:|---|")
        println(simFleet(options))
        println(router(options))
        coroutineContext.cancelChildren()
    }
}

private data class ThreadOptions(val vehicles: Int, val routeLinks: Int, val window: Duration)

private class LinkThreadsCommand : BenchCommand<ThreadOptions>("LinkThreadsKt", "Threads of a simulated fleet and a router with many links.") {
    private val vehicles by option("--vehicles").count(1..254).default(250)
    private val routeLinks by option("--route-links").count(2..1000).default(50)
    private val window by option("--window", help = "CPU measured over").duration(1.seconds..10.minutes).default(10.seconds)

    override fun options(): ThreadOptions = ThreadOptions(vehicles, routeLinks, window)
}

private suspend fun CoroutineScope.simFleet(options: ThreadOptions): String {
    val before = liveThreads()
    val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false))
    val fleet = SimFleet.start(options.vehicles, this, SimVehicleConfig(systemId = 1, gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
    try {
        withTimeout(2.minutes) { gcs.vehicles.first { it.size >= options.vehicles } }
        return row("SimFleet of ${options.vehicles} + its station", before, options.window)
    } finally {
        fleet.stop()
        gcs.closeAndAwait()
    }
}

private suspend fun CoroutineScope.router(options: ThreadOptions): String {
    val before = liveThreads()
    val router = MavlinkRouter.open(List(options.routeLinks) { "udpin://127.0.0.1:0" }, this)
    try {
        delay(1.seconds) // every link's receive started
        return row("MavlinkRouter of ${options.routeLinks} UDP links", before, options.window)
    } finally {
        router.close()
    }
}

private suspend fun row(what: String, before: Int, window: Duration): String {
    val os = ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean
    val running = liveThreads()
    val receiving = Thread.getAllStackTraces().keys.count { it.isAlive && it.name.startsWith("pod-udp-receive") }
    val cpu0 = os.processCpuTime
    val t0 = System.nanoTime()
    delay(window)
    val cpu = (os.processCpuTime - cpu0).toDouble() / (System.nanoTime() - t0)
    val load = File("/proc/loadavg").readText().split(" ").take(3).joinToString(" ")
    return "| %s | %d | %d | %d | %.1f | %s |".format(what, before, running, receiving, cpu * 100, load)
}

private fun liveThreads(): Int = ManagementFactory.getThreadMXBean().threadCount
