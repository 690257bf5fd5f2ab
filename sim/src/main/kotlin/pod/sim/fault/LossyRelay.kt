package pod.sim.fault

import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.MavlinkLink
import java.net.InetAddress
import java.net.UnknownHostException
import kotlin.random.Random
import pod.core.time.Timebase

/**
 * A UDP relay on loopback that sits between two MAVLink endpoints, A and B, and applies [aToB] to
 * what A sends and [bToA] to what B sends.
 *
 * Each side is a connection string, as for [MavlinkLink]:
 * - `udpin://127.0.0.1:0` listens; the relay learns that side's peers from their datagrams and
 *   sends the other side's traffic to every peer it has heard (so several vehicles can share one
 *   side). Until a listening side has heard from someone, traffic for it is discarded and counted.
 * - `udpout://127.0.0.1:PORT` sends to a listener on PORT from an ephemeral port.
 *
 * So `LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:14550")` serves both a ground
 * station listening on 14550 with vehicles sending to [portA], and a ground station that sends
 * first (to [portA]) to a vehicle listening on 14550. With both sides `udpin`, both ends send to
 * the relay ([portA] and [portB]).
 *
 * Both directions draw from their own [FaultModel], seeded from [seed], so a run is repeatable as
 * far as the traffic itself is. Only loopback addresses are accepted: this is a test instrument.
 * Its clock and the dispatcher it relays on are [timebase]'s. (For faults without sockets, put
 * [FaultConditions] on a [pod.mavlink.link.MemoryNetwork].)
 */
public class LossyRelay(
    /** Side A. */
    public val a: LinkAddress,
    /** Side B. */
    public val b: LinkAddress,
    /** Faults on datagrams going from A to B. */
    public val aToB: LinkFaults = LinkFaults.None,
    /** Faults on datagrams going from B to A. */
    public val bToA: LinkFaults = LinkFaults.None,
    /** Seed from which each direction's own seed is derived. */
    public val seed: Long = 0,
    /** Most datagrams each direction keeps waiting, in its inbox and in its schedule each. */
    public val queueCapacity: Int = DEFAULT_QUEUE_CAPACITY,
    /** The clock that times deliveries and the dispatcher the relay runs on. */
    public val timebase: Timebase = Timebase.System,
) {
    /** Parses [a] and [b] as connection strings (see [LinkAddress.parse]). */
    public constructor(
        a: String,
        b: String,
        aToB: LinkFaults = LinkFaults.None,
        bToA: LinkFaults = LinkFaults.None,
        seed: Long = 0,
        queueCapacity: Int = DEFAULT_QUEUE_CAPACITY,
        timebase: Timebase = Timebase.System,
    ) : this(LinkAddress.parse(a), LinkAddress.parse(b), aToB, bToA, seed, queueCapacity, timebase)

    init {
        requireLoopbackUdp("a", a)
        requireLoopbackUdp("b", b)
        require(queueCapacity >= 1) { "queueCapacity must be ≥ 1, was $queueCapacity" }
    }

    private val _counters = MutableStateFlow(RelayCounters())

    @Volatile private var linkA: MavlinkLink? = null

    @Volatile private var linkB: MavlinkLink? = null

    @Volatile private var job: Job? = null

    /** What happened to each direction so far; await a state with `counters.first { … }`. */
    public val counters: StateFlow<RelayCounters> = _counters.asStateFlow()

    /** The local port of side A's socket. Throws [IllegalStateException] before [start]. */
    public val portA: Int get() = checkNotNull(linkA) { "LossyRelay is not started" }.localPort

    /** The local port of side B's socket. Throws [IllegalStateException] before [start]. */
    public val portB: Int get() = checkNotNull(linkB) { "LossyRelay is not started" }.localPort

    /**
     * Binds both sides now (a taken port fails here, with the link's [pod.mavlink.link.LinkException])
     * and relays in a child of [scope] until [close] is called or [scope] ends. Start it once.
     */
    public suspend fun start(scope: CoroutineScope) {
        check(job == null) { "LossyRelay was already started" }
        val sideA = MavlinkLink.open(a)
        val sideB = try {
            MavlinkLink.open(b)
        } catch (e: Throwable) {
            sideA.close()
            throw e
        }
        linkA = sideA
        linkB = sideB
        val seeds = Random(seed)
        val started = timebase.clock.markNow()
        val clock = { started.elapsedNow() }
        val forward = RelayLeg(FaultModel(aToB, seeds.nextLong()), queueCapacity, clock) { leg ->
            _counters.update { it.copy(aToB = leg) }
        }
        val backward = RelayLeg(FaultModel(bToA, seeds.nextLong()), queueCapacity, clock) { leg ->
            _counters.update { it.copy(bToA = leg) }
        }
        val relaying = scope.launch(timebase.dispatcher + CoroutineName("LossyRelay $a <-> $b")) {
            launch { sideA.receive { _, bytes -> forward.accept(bytes) } }
            launch { sideB.receive { _, bytes -> backward.accept(bytes) } }
            launch { forward.run(sideB) }
            launch { backward.run(sideA) }
        }
        // However the relay ends (close, the owner's scope cancelled, a failure), the ports are freed.
        relaying.invokeOnCompletion {
            sideA.close()
            sideB.close()
        }
        job = relaying
    }

    /** Stops relaying and frees both ports; datagrams still waiting are not delivered. Safe to call twice. */
    public fun close() {
        job?.cancel()
        linkA?.close()
        linkB?.close()
    }

    /** Defaults of a relay. */
    public companion object {
        /** Default for [queueCapacity]: a few seconds of a busy fleet's telemetry. */
        public const val DEFAULT_QUEUE_CAPACITY: Int = 4096

        private fun requireLoopbackUdp(side: String, address: LinkAddress) {
            require(address is LinkAddress.UdpIn || address is LinkAddress.UdpOut) {
                "$side must be a udpin:// or udpout:// address, was $address"
            }
            val resolved = try {
                InetAddress.getAllByName(address.host).toList()
            } catch (e: UnknownHostException) {
                emptyList()
            }
            require(resolved.isNotEmpty() && resolved.all { it.isLoopbackAddress }) {
                "$side must be on loopback (127.0.0.1, ::1 or localhost), was ${address.host}"
            }
        }
    }
}

/** A [LossyRelay]'s counters, one set per direction. */
public data class RelayCounters(
    /** Datagrams from side A towards side B. */
    public val aToB: LinkCounters = LinkCounters(),
    /** Datagrams from side B towards side A. */
    public val bToA: LinkCounters = LinkCounters(),
)
