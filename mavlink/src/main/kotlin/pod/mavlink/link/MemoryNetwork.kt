package pod.mavlink.link

import io.ktor.network.sockets.InetSocketAddress
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import pod.core.time.Timebase
import kotlin.time.Duration
import kotlin.time.TimeMark

/**
 * UDP without sockets: links that hand datagrams to each other in memory, on a [Timebase]'s
 * dispatcher and clock. Under kotlinx-coroutines-test's scheduler a ground station and simulated
 * vehicles on one network run in virtual time, deterministic for a seed, with no real-time
 * deadline.
 *
 * [open] takes the same addresses as [MavlinkLink.open] and behaves as UDP does: `udpin://H:P`
 * binds H:P (port 0: the next free one) and learns its peers from what arrives; `udpout://H:P`
 * binds an ephemeral port and talks to H:P. A datagram to an address nobody holds is lost; a
 * receiver whose queue is full ([RECEIVE_QUEUE] datagrams, as a socket's buffer) loses it too.
 *
 * [conditions] gives each direction between two local addresses what goes wrong on it (a seeded
 * fault model: loss, duplication, reordering, delay); null, the default, is a perfect link that
 * delivers at once.
 *
 * Every coroutine a network starts is a child of [scope]; cancelling it stops them all.
 */
public class MemoryNetwork(
    private val scope: CoroutineScope,
    private val timebase: Timebase = Timebase.System,
    private val conditions: (from: InetSocketAddress, to: InetSocketAddress) -> LinkConditions? = { _, _ -> null },
) {
    private val bound = HashMap<InetSocketAddress, Endpoint>()
    private val routes = HashMap<Pair<InetSocketAddress, InetSocketAddress>, Route>()
    private var nextEphemeral = FIRST_EPHEMERAL
    private val started: TimeMark = timebase.clock.markNow()

    /** Opens a link on [address] (`udpin` or `udpout`; TCP has no in-memory form). */
    public fun open(address: LinkAddress): MavlinkLink = synchronized(this) {
        val local = when (address) {
            is LinkAddress.UdpIn -> InetSocketAddress(address.host, if (address.port == 0) ephemeral() else address.port)
            is LinkAddress.UdpOut -> InetSocketAddress(LOOPBACK, ephemeral())
            is LinkAddress.Tcp, is LinkAddress.Replay, is LinkAddress.Serial -> throw LinkException("a memory network carries UDP only, not $address")
        }
        if (local in bound) throw PortInUse(address)
        val remote = (address as? LinkAddress.UdpOut)?.let { LinkPeer(InetSocketAddress(it.host, it.port)) }
        Endpoint(address, local, remote).also { bound[local] = it }
    }

    /** Parses [connection] (see [LinkAddress.parse]) and opens it. */
    public fun open(connection: String): MavlinkLink = open(LinkAddress.parse(connection))

    private fun ephemeral(): Int {
        while (bound.keys.any { it.port == nextEphemeral }) nextEphemeral++
        return nextEphemeral++
    }

    private fun now(): Duration = started.elapsedNow()

    private fun deliver(from: Endpoint, bytes: ByteArray, to: InetSocketAddress) {
        val copy = bytes.copyOf() // the sender may reuse its array, as it may a socket's
        val route = synchronized(this) {
            routes.getOrPut(from.local to to) { Route(from.local, to, conditions(from.local, to)) }
        }
        val model = route.conditions
        if (model == null) {
            arrive(route, copy)
            return
        }
        val now = now()
        val deliveries = synchronized(route) { model.offer(copy, now) }
        schedule(route, deliveries, now)
        armRelease(route)
    }

    private fun schedule(route: Route, deliveries: List<TimedDatagram>, now: Duration) {
        for (d in deliveries) {
            if (d.at <= now) {
                arrive(route, d.bytes)
            } else {
                scope.launch(timebase.dispatcher) {
                    delay(d.at - now)
                    arrive(route, d.bytes)
                }
            }
        }
    }

    /** Keeps one timer at the route's next release of held datagrams. */
    private fun armRelease(route: Route) {
        val model = route.conditions ?: return
        val at = synchronized(route) { model.nextRelease } ?: return
        synchronized(route) {
            if (route.releaseAt != null && route.releaseAt!! <= at) return
            route.releaseAt = at
        }
        scope.launch(timebase.dispatcher) {
            delay(at - now())
            val now = now()
            val released = synchronized(route) {
                route.releaseAt = null
                model.release(now)
            }
            schedule(route, released, now)
            armRelease(route)
        }
    }

    private fun arrive(route: Route, bytes: ByteArray) {
        val target = synchronized(this) { bound[route.to] ?: bound.entries.firstOrNull { it.key.port == route.to.port && it.key.hostname == ANY }?.value }
        target?.inbox?.trySend(Arrival(route.from, bytes))
    }

    private class Route(val from: InetSocketAddress, val to: InetSocketAddress, val conditions: LinkConditions?) {
        var releaseAt: Duration? = null
    }

    private class Arrival(val from: InetSocketAddress, val bytes: ByteArray)

    private inner class Endpoint(
        override val address: LinkAddress,
        val local: InetSocketAddress,
        private val remote: LinkPeer?,
    ) : MavlinkLink {
        val inbox = Channel<Arrival>(RECEIVE_QUEUE)
        @Volatile private var closed = false
        private val heard = LinkedHashSet<LinkPeer>()
        private val peersByAddress = HashMap<InetSocketAddress, LinkPeer>()

        override val localPort: Int get() = local.port

        override val peers: Collection<LinkPeer>
            get() = remote?.let { listOf(it) } ?: synchronized(heard) { heard.toList() }

        override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
            for (arrival in inbox) {
                val peer = peersByAddress.getOrPut(arrival.from) {
                    LinkPeer(arrival.from).also { if (remote == null) synchronized(heard) { heard += it } }
                }
                onBytes(peer, arrival.bytes)
            }
        }

        override suspend fun send(bytes: ByteArray, peer: LinkPeer) = sendNow(bytes, peer)

        override val sendsInPlace: Boolean get() = true

        override fun sendNow(bytes: ByteArray, peer: LinkPeer) {
            val to = peer.address as? InetSocketAddress ?: return
            if (closed) return
            deliver(this, bytes, to)
        }

        override fun close() {
            closed = true
            inbox.close()
            synchronized(this@MemoryNetwork) { bound.remove(local, this) }
        }

        override fun toString(): String = "memory link $address (${local.hostname}:${local.port})"
    }

    /** The limits of a memory network, as a socket's would be. */
    public companion object {
        /** Datagrams a receiver holds before it loses more, as a socket's receive buffer would. */
        public const val RECEIVE_QUEUE: Int = 4096

        private const val FIRST_EPHEMERAL = 40000
        private const val LOOPBACK = "127.0.0.1"
        private const val ANY = "0.0.0.0"
    }
}

/**
 * What goes wrong on one direction of a [MemoryNetwork] route, as a pure machine driven with the
 * network's clock (time since the network was made): pod-sim's seeded fault model is one.
 */
public interface LinkConditions {
    /** Datagram [bytes] is sent at [now]: the copies to deliver and when (none: it is lost). */
    public fun offer(bytes: ByteArray, now: Duration): List<TimedDatagram>

    /** When datagrams held back (for reordering) must go out at the latest, or null when none are. */
    public val nextRelease: Duration?

    /** The held datagrams due at [now]. */
    public fun release(now: Duration): List<TimedDatagram>
}

/** A datagram to deliver at [at] (on the [MemoryNetwork]'s clock). */
public class TimedDatagram(
    /** When it arrives. */
    public val at: Duration,
    /** What arrives. */
    public val bytes: ByteArray,
)
