package pod.mavlink.route

import kotlinx.coroutines.channels.Channel
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration

/**
 * One link of a [MavlinkRouter] and the endpoints routed on it: every peer of a listening
 * (`udpin`) link is an endpoint of its own, as each may be another ground station or vehicle;
 * any other link (`udpout`, TCP) is one endpoint, its remote.
 *
 * mavlink-router's UDP server endpoint keeps one remote address, the last one a datagram came
 * from (src/mavlink-router/endpoint.cpp, `UdpEndpoint::_read_msg` overwrites `sockaddr`), so two
 * ground stations on one server port steal each other's replies; here each keeps its own routes.
 *
 * [endpoints] is guarded by the router's lock; the counters are atomic (bumped from the receive
 * threads of every link).
 */
internal class RoutePort(
    val link: MavlinkLink,
    /** True when the router does not receive on [link] itself: a ground station feeds it ([MavlinkRouter.fromStation]). */
    val fedFromOutside: Boolean,
    private val codec: MessageCodec,
    private val capacity: Int,
    sendQueue: Int,
) {
    /** Whether each sender is an endpoint of its own. */
    val perPeer: Boolean = link.address is LinkAddress.UdpIn

    val received = AtomicLong()
    val forwarded = AtomicLong()
    val unrouted = AtomicLong()
    val evicted = AtomicLong()
    val sendDrops = AtomicLong()
    private val retiredBadCrc = AtomicLong()

    @Volatile var error: String? = null

    /** Frames waiting to go out on a link that cannot send in place; drained by the router. */
    val outbox: Channel<Outgoing>? = if (link.sendsInPlace) null else Channel(sendQueue)

    /** Access order: iteration starts at the endpoint heard least recently. */
    val endpoints = LinkedHashMap<LinkPeer, RouteEndpoint>(16, 0.75f, true)

    /** The endpoint frames from [peer] belong to: the peer itself on a listening link, else the link. */
    fun keyOf(peer: LinkPeer): LinkPeer = if (perPeer) peer else WHOLE_LINK

    /**
     * The endpoint for [key], made (and added to [table]) when new, marked heard at [now]; beyond
     * [capacity] the least recent one is forgotten. Call under the router's lock.
     */
    fun endpointFor(key: LinkPeer, now: Duration, table: RouteTable<RouteEndpoint>): RouteEndpoint {
        val endpoint = endpoints.getOrPut(key) { RouteEndpoint(this, key, if (fedFromOutside) null else FrameDecoder(codec)).also(table::add) }
        endpoint.lastHeard = now
        while (endpoints.size > capacity) forget(endpoints.values.first(), table, evicting = true)
        return endpoint
    }

    /** Drops [endpoint] and its routes. Call under the router's lock. */
    fun forget(endpoint: RouteEndpoint, table: RouteTable<RouteEndpoint>, evicting: Boolean) {
        if (endpoints[endpoint.peer] === endpoint) endpoints.remove(endpoint.peer)
        table.remove(endpoint)
        endpoint.decoder?.let { retiredBadCrc.addAndGet(it.stats.badCrc) }
        if (evicting) evicted.incrementAndGet()
    }

    /** Counters now; [peers] is read under the router's lock by the caller. */
    fun stats(peers: Int, liveBadCrc: Long): RouteLinkStats = RouteLinkStats(
        address = link.address.toString(),
        peers = peers,
        received = received.get(),
        forwarded = forwarded.get(),
        unrouted = unrouted.get(),
        badCrc = retiredBadCrc.get() + liveBadCrc,
        evictedPeers = evicted.get(),
        sendDrops = sendDrops.get(),
        error = error,
    )

    companion object {
        /** The key of the one endpoint of a link that is not listening. */
        val WHOLE_LINK: LinkPeer = LinkPeer("whole link")
    }
}

/** A frame queued for a link that sends by suspending; [peer] null: to all its peers. */
internal class Outgoing(val bytes: ByteArray, val peer: LinkPeer?)

/** One place frames come from and go to: a peer of a listening link, or a whole link. */
internal class RouteEndpoint(
    val port: RoutePort,
    val peer: LinkPeer,
    /** Reassembles this endpoint's bytes into frames; null on a port fed frames already decoded. */
    val decoder: FrameDecoder?,
) {
    /** When a frame was last heard from here, on the router's clock. */
    @Volatile var lastHeard: Duration = Duration.ZERO

    override fun toString(): String = if (peer == RoutePort.WHOLE_LINK) "${port.link.address}" else "${port.link.address} peer $peer"
}
