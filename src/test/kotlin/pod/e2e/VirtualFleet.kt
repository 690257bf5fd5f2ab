package pod.e2e

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withTimeout
import pod.core.engine.EngineEvent
import pod.core.engine.Program
import pod.core.platform.PlatformVehicle
import pod.core.time.Timebase
import pod.launch.SimRecord
import pod.launch.simulate
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkConditions
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.link.TimedDatagram
import pod.sim.LinkOpener
import pod.sim.SimFleet
import pod.sim.SimFlavor
import pod.sim.SimPlatform
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.fault.FaultConditions
import pod.sim.fault.LinkCounters
import pod.sim.fault.LinkFaults
import java.util.concurrent.ConcurrentHashMap
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * One seeded virtual world for end-to-end behaviour: kotlinx-coroutines-test's scheduler as the
 * clock of the engine, the ground station and every simulated vehicle, all on one [MemoryNetwork].
 * Datagrams towards a listening link (the ground station's `udpin`) suffer [up], all others
 * [down], each route from its own [FaultConditions] seeded from [seed]. Vehicles run at time
 * scale 1: vehicle time is virtual time, so bounds here are in vehicle time and cost no wall time.
 */
internal class VirtualFleet(
    val test: TestScope,
    val seed: Long,
    up: LinkFaults,
    down: LinkFaults,
    withheldAtStart: Set<Int> = emptySet(),
) {
    /**
     * Message ids that do not reach a listening link (a stream the vehicle does not send yet, as a
     * station sees it); a test may change it while the world runs.
     */
    val withheld: MutableSet<Int> = ConcurrentHashMap.newKeySet<Int>().also { it += withheldAtStart }
    /** The test scheduler's clock and a dispatcher on it. */
    val timebase = Timebase(test.testScheduler.timeSource, StandardTestDispatcher(test.testScheduler))

    private val listening: MutableSet<Int> = ConcurrentHashMap.newKeySet()

    /**
     * Every datagram offered towards a listening link, as "virtual-ms hex-bytes", in the order
     * sent (before faults): what the vehicles said, for golden traces of their behaviour.
     */
    val towardsGround: MutableList<String> = java.util.Collections.synchronizedList(ArrayList())

    private val routes = FaultConditions.byDirection(seed, up, down) { it in listening }
    private val models: MutableList<Pair<Boolean, FaultConditions>> = java.util.Collections.synchronizedList(ArrayList())

    /** The in-memory network everything talks over. */
    val network = MemoryNetwork(test.backgroundScope, timebase) { from, to ->
        val faults = routes(from, to)?.also { models += (to.port in listening) to it }
        if (to.port !in listening) faults else Withholding(withheld, faults, towardsGround)
    }

    /** What the faults did so far to datagrams towards the ground ([towardsGround]) or away from it, summed over routes. */
    fun counters(towardsGround: Boolean): LinkCounters = synchronized(models) {
        models.filter { it.first == towardsGround }.map { it.second.model.counters }
            .fold(LinkCounters()) { a, b -> LinkCounters(a.sent + b.sent, a.dropped + b.dropped, a.duplicated + b.duplicated, a.reordered + b.reordered, a.corrupted + b.corrupted, a.delivered + b.delivered) }
    }

    /** Opens links on [network], noting the ports that listen (the ground side of [up]). */
    val openLink = LinkOpener { address ->
        network.open(address).also { if (address is LinkAddress.UdpIn) listening += it.localPort }
    }

    /** [pod.launch.simulate] on this world: [flavors] at time scale 1, the engine on the virtual clock. */
    suspend fun <T> simulate(
        flavors: List<SimFlavor>,
        onEvent: (EngineEvent) -> Unit = {},
        station: GroundStationConfig = GroundStationConfig(),
        configure: (SimVehicleConfig) -> SimVehicleConfig = { it },
        program: suspend Program.(SimPlatform) -> T,
    ): Pair<T, SimRecord> =
        simulate(flavors, timeScale = 1.0, onEvent = onEvent, timebase = timebase, openLink = openLink, station = station, configure = configure, program = program)

    /** A started [SimPlatform] of [flavors] on this world (see [SimPlatform.start]). */
    suspend fun platform(scope: CoroutineScope, flavors: List<SimFlavor>): SimPlatform =
        SimPlatform.start(scope, flavors, timeScale = 1.0, timebase = timebase, openLink = openLink)

    /** One vehicle of [flavor] on a fresh platform; everything stops afterwards. */
    suspend fun withVehicle(
        flavor: SimFlavor,
        block: suspend CoroutineScope.(SimPlatform, PlatformVehicle, MavlinkVehicle, SimVehicle) -> Unit,
    ) = coroutineScope {
        val fleet = platform(this, listOf(flavor))
        try {
            val v = fleet.vehicles.value.single()
            block(fleet, v, fleet.platform.mavlink(v), fleet.simulated.single())
        } finally {
            fleet.close()
        }
    }

    /** A ground station on this world listening on a fresh port. */
    fun station(scope: CoroutineScope, config: GroundStationConfig = GroundStationConfig()): GroundStation =
        GroundStation.open(network.open("udpin://127.0.0.1:0").also { listening += it.localPort }, scope, config.copy(timebase = timebase))

    /** A vehicle of [config] (time scale 1) sending to [gcs] on this world; not started. */
    fun vehicle(config: SimVehicleConfig, gcs: GroundStation): SimVehicle =
        SimVehicle(sendingTo(config, gcs), timebase = timebase, openLink = openLink)

    /** [count] vehicles like [config] (system ids from its own, see [SimFleet.start]) sending to [gcs] on this world, started in [scope]. */
    suspend fun fleet(scope: CoroutineScope, count: Int, config: SimVehicleConfig, gcs: GroundStation): SimFleet =
        SimFleet.start(count, scope, sendingTo(config, gcs), timebase = timebase, openLink = openLink)

    private fun sendingTo(config: SimVehicleConfig, gcs: GroundStation) =
        config.copy(gcs = "udpout://127.0.0.1:${gcs.link.localPort}", timeScale = 1.0)

    /**
     * One vehicle of [config] and a station: [block] once the station has heard the vehicle
     * (within 10 s of vehicle time); both stop afterwards.
     */
    suspend fun heard(
        config: SimVehicleConfig,
        station: GroundStationConfig = GroundStationConfig(),
        block: suspend CoroutineScope.(MavlinkVehicle, SimVehicle) -> Unit,
    ) = withStation(config, station, { gcs -> withTimeout(10.seconds) { gcs.vehicles.first { config.systemId in it } }.getValue(config.systemId) }, block)

    /**
     * [Flights.flying] on this world: one vehicle of [config] and a station, [block] once the
     * vehicle can arm; both stop afterwards.
     */
    suspend fun flying(
        config: SimVehicleConfig,
        station: GroundStationConfig = GroundStationConfig(),
        block: suspend CoroutineScope.(MavlinkVehicle, SimVehicle) -> Unit,
    ) = withStation(config, station, { gcs -> Flights.vehicle(gcs, config.systemId) }, block)

    private suspend fun withStation(
        config: SimVehicleConfig,
        station: GroundStationConfig,
        await: suspend (GroundStation) -> MavlinkVehicle,
        block: suspend CoroutineScope.(MavlinkVehicle, SimVehicle) -> Unit,
    ) = coroutineScope {
        val gcs = station(this, station)
        val sim = vehicle(config, gcs)
        try {
            sim.start(this)
            block(await(gcs), sim)
        } finally {
            sim.stop()
            gcs.close()
        }
    }
}

/**
 * Runs [block] in a fresh [VirtualFleet] under `runTest`. [timeout] is runTest's real-time guard
 * against a hang, not a bound on behaviour.
 */
internal fun virtualRun(
    seed: Long = 1,
    up: LinkFaults = LinkFaults.None,
    down: LinkFaults = LinkFaults.None,
    timeout: Duration = 3.minutes,
    withheld: Set<Int> = emptySet(),
    block: suspend VirtualFleet.() -> Unit,
) = runTest(timeout = timeout) {
    VirtualFleet(this, seed, up, down, withheld).block()
}

/** Drops every datagram that carries one of the message ids [withheld] and passes the rest to [faults]. */
private class Withholding(
    private val withheld: Set<Int>,
    private val faults: LinkConditions?,
    private val record: MutableList<String>,
) : LinkConditions {
    override fun offer(bytes: ByteArray, now: Duration): List<TimedDatagram> {
        record += "${now.inWholeMicroseconds} ${bytes.joinToString("") { "%02x".format(it) }}"
        return pass(bytes, now)
    }

    private fun pass(bytes: ByteArray, now: Duration): List<TimedDatagram> = when {
        messageId(bytes) in withheld -> emptyList()
        faults == null -> listOf(TimedDatagram(now, bytes))
        else -> faults.offer(bytes, now)
    }

    override val nextRelease: Duration? get() = faults?.nextRelease

    override fun release(now: Duration): List<TimedDatagram> = faults?.release(now) ?: emptyList()

    /** The message id of the datagram's first frame (MAVLink 2: bytes 7..9, little-endian; MAVLink 1: byte 5), or -1. */
    private fun messageId(bytes: ByteArray): Int = when {
        bytes.size >= 10 && bytes[0] == 0xFD.toByte() -> (bytes[7].toInt() and 0xFF) or ((bytes[8].toInt() and 0xFF) shl 8) or ((bytes[9].toInt() and 0xFF) shl 16)
        bytes.size >= 6 && bytes[0] == 0xFE.toByte() -> bytes[5].toInt() and 0xFF
        else -> -1
    }
}

/** The engine's events as comparable lines (an error compares by its type and message). */
internal fun List<EngineEvent>.trace(): List<String> = map { it.toString() }
