package pod.bench.command

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import pod.bench.percentile
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.VehicleCommand
import pod.mavlink.link.MavlinkLink
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * MAV_CMD_SET_MESSAGE_INTERVAL (511) for SYS_STATUS (1) at 1,000,000 µs: the simulated vehicles'
 * own rate, so commanding leaves their streams as they were. Both ground stations send this.
 */
val BENCH_COMMAND = VehicleCommand(command = 511, param1 = 1f, param2 = 1_000_000f)

/** How one command of a round went, as its caller saw it (System.nanoTime). */
private class Sample(val systemId: Int, val calledAt: Long, val returnedAt: Long, val error: String?) {
    val ok: Boolean get() = error == null
}

/**
 * One round: [BENCH_COMMAND] to every vehicle at once, one coroutine each, every send bounded by
 * [limit] on top of Pod's own timeout. With a [tap], also the per-command split of the latency.
 */
internal suspend fun podRound(vehicles: List<MavlinkVehicle>, tap: CommandTap?, limit: Duration, split: MutableList<DoubleArray>? = null): CommandRound {
    tap?.resetRound()
    val sentBefore = tap?.commandsSent ?: 0
    val start = System.nanoTime()
    val samples = coroutineScope {
        vehicles.map { vehicle ->
            async {
                val calledAt = System.nanoTime()
                val error = try {
                    val reply = withTimeoutOrNull(limit) { vehicle.commands.send(BENCH_COMMAND) }
                    if (reply == null) "no outcome within $limit (harness limit)" else null
                } catch (e: CancellationException) {
                    if (e is TimeoutCancellationException) "harness limit" else throw e
                } catch (e: Exception) {
                    // CommandTimeout, CommandRejected, VehicleLost: a failed command, counted.
                    "vehicle ${vehicle.systemId}: ${e::class.simpleName}: ${e.message}"
                }
                Sample(vehicle.systemId, calledAt, System.nanoTime(), error)
            }
        }.awaitAll()
    }
    val acked = samples.filter { it.ok }
    val end = acked.maxOfOrNull { it.returnedAt } ?: samples.maxOf { it.returnedAt }
    if (tap != null && split != null) {
        for (s in acked) {
            val sent = tap.sentAt(s.systemId)
            val sendReturned = tap.sendReturnedAt(s.systemId)
            val ack = tap.ackedAt(s.systemId)
            if (tap.sends(s.systemId) == 1 && sent != 0L && sendReturned != 0L && ack != 0L) {
                split += doubleArrayOf((sent - s.calledAt) / 1e3, (sendReturned - sent) / 1e3, (ack - sendReturned) / 1e3, (s.returnedAt - ack) / 1e3)
            }
        }
    }
    return CommandRound(
        latenciesUs = acked.map { (it.returnedAt - it.calledAt) / 1e3 },
        makespanUs = (end - start) / 1e3,
        failures = samples.size - acked.size,
        sends = if (tap != null) (tap.commandsSent - sentBefore).toInt() else samples.size,
        errors = samples.mapNotNull { it.error },
    )
}

/**
 * Pod's GroundStation (fresh, in this JVM, no stream-rate requests) against a fresh fleet of the
 * [fleet] process: discovery (timed, not part of the figures), [CommandCase.warmUp] discarded
 * rounds, then [CommandCase.rounds] measured ones, [gap] apart.
 */
suspend fun podRun(case: CommandCase, fleet: FleetProcess, o: CommandBenchOptions): CommandRun = coroutineScope {
    val tap = CommandTap(MavlinkLink.open("udpin://127.0.0.1:0"))
    // Heartbeats cross the lossy relays too: the default 3 s would call a vehicle lost now and then.
    val gcs = GroundStation.open(tap, this, GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, lostAfter = 30.seconds))
    var stopped: Map<String, String>? = null
    try {
        fleet.start(case, o.seed, gcs.link.localPort)?.let { return@coroutineScope CommandRun(CommandStation.POD, case, emptyList(), setupError = it) }
        val discoveryStart = System.nanoTime()
        val all = withTimeoutOrNull(o.discovery) { gcs.vehicles.first { it.size >= case.vehicles } }
            ?: return@coroutineScope CommandRun(
                CommandStation.POD, case, emptyList(),
                setupError = "${gcs.vehicles.value.size} of ${case.vehicles} vehicles discovered within ${o.discovery}",
            )
        val discovery = (System.nanoTime() - discoveryStart) / 1e9
        val vehicles = all.values.sortedBy { it.systemId }
        val split = ArrayList<DoubleArray>()
        val rounds = ArrayList<CommandRound>()
        var gcsCpu = 0.0
        var fleetCpu: Double? = null
        repeat(case.warmUp + case.rounds) { r ->
            if (r == case.warmUp) {
                gcsCpu = processCpuSeconds()
                fleetCpu = fleet.cpuSeconds()
            }
            val measured = r >= case.warmUp
            val round = podRound(vehicles, tap, ROUND_LIMIT, if (measured) split else null)
            if (measured) rounds += round
            delay(o.gap)
        }
        gcsCpu = processCpuSeconds() - gcsCpu
        fleetCpu = fleet.cpuSeconds()?.let { end -> fleetCpu?.let { end - it } }
        gcs.close()
        stopped = fleet.stop()
        CommandRun(
            CommandStation.POD, case, rounds, discovery,
            split = if (split.isEmpty()) null else PodSplit(
                split.size, percentile(split.map { it[0] }, 50.0), percentile(split.map { it[1] }, 50.0),
                percentile(split.map { it[2] }, 50.0), percentile(split.map { it[3] }, 50.0),
            ),
            droppedToGcs = stopped["droppedToGcs"]?.toLongOrNull() ?: 0, droppedToVehicle = stopped["droppedToVehicle"]?.toLongOrNull() ?: 0,
            gcsCpuSeconds = gcsCpu, fleetCpuSeconds = fleetCpu,
        )
    } finally {
        gcs.close()
        if (stopped == null) fleet.stop()
        coroutineContext.cancelChildren()
    }
}

/** Bound on each command on top of Pod's own 10 s silence timeout. */
private val ROUND_LIMIT = 30.seconds
