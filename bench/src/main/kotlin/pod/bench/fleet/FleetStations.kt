package pod.bench.fleet

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.flow.first
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import java.io.File
import java.util.concurrent.TimeUnit

/**
 * The stations of a fleet run and the sender JVMs that feed them: one [GroundStation] per link in
 * this JVM, each hearing `vehicles / links` vehicles (system ids from 1 on every link, as separate
 * radios or fleets would), each link's vehicles spread over its share of the sender JVMs.
 */
internal class FleetStations private constructor(
    val stations: List<GroundStation>,
    private val perLink: List<Int>,
    private val senders: List<Process>,
) {
    /** Suspends until every link heard all of its vehicles. */
    suspend fun awaitVehicles() {
        for ((station, count) in stations.zip(perLink)) station.vehicles.first { it.size >= count }
    }

    fun found(): Int = stations.sumOf { it.vehicles.value.size }

    /** Frames the stations decoded so far, all links. */
    fun frames(): Long = stations.sumOf { it.stats.value.frames }

    fun sendersCpuNanos(): Long = senders.sumOf { p -> p.toHandle().info().totalCpuDuration().map { it.toNanos() }.orElse(0L) }

    suspend fun close() {
        senders.forEach { it.outputStream.close(); it.destroy() }
        senders.forEach { it.waitFor(5, TimeUnit.SECONDS) }
        stations.forEach { it.closeAndAwait() }
    }

    companion object {
        suspend fun open(scope: CoroutineScope, options: Options): FleetStations {
            val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false)
            val stations = List(options.links) { GroundStation.open("udpin://127.0.0.1:0", scope, config) }
            val perLink = spread(options.vehicles, options.links)
            val sendersPerLink = spread(options.senders, options.links)
            val java = File(System.getProperty("java.home"), "bin/java").path
            val senders = stations.indices.flatMap { link ->
                val counts = spread(perLink[link], sendersPerLink[link])
                counts.indices.filter { counts[it] > 0 }.map { i ->
                    ProcessBuilder(
                        java, "-Xms128m", "-Xmx128m", "-XX:+UseSerialGC", "-cp", System.getProperty("java.class.path"),
                        "pod.bench.fleet.FleetSenderKt", "--port", stations[link].link.localPort.toString(),
                        "--first", (1 + counts.take(i).sum()).toString(), "--count", counts[i].toString(),
                    ).redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(ProcessBuilder.Redirect.INHERIT).start()
                }
            }
            return FleetStations(stations, perLink, senders)
        }

        /** [total] in [parts] shares as even as can be, the larger ones first. */
        private fun spread(total: Int, parts: Int): List<Int> = List(parts) { i -> total / parts + if (i < total % parts) 1 else 0 }
    }
}
