package pod.mavlink.route

import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.job
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.LinkException
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * Forwards MAVLink between links as mavlink-router does, so that several ground stations (Pod
 * programs, `pod watch`, QGroundControl, MAVProxy) share one vehicle, or one station many vehicles
 * behind several links.
 *
 * Every frame heard is checked (CRC) and goes, with its original bytes unchanged (a signed frame
 * stays valid), to each endpoint where its target was heard, or to every other endpoint when it is
 * a broadcast; never back where it came from, and once per endpoint. The rules and their source
 * are in [RouteTable]; an endpoint is a peer of a listening link or a whole other link
 * ([RoutePort]). Targets are read from the payload's bytes ([FrameTargets]), nothing is decoded.
 *
 * Frames are routed on the receive path of the link they arrived on (a UDP receive thread the link shares with others) and
 * sent from there when the destination sends in place (UDP); a TCP destination gets a bounded
 * queue. Memory is bounded by [RouterConfig]. All coroutines are children of the scope it was
 * started in; [close] stops them and closes the links it was given.
 *
 * ```
 * val router = MavlinkRouter.open(listOf("udpin:0.0.0.0:14550", "udpout:127.0.0.1:14551"), scope)
 * ```
 */
public class MavlinkRouter private constructor(
    private val ports: List<RoutePort>,
    parent: CoroutineScope,
    /** Bounds and clock. */
    public val config: RouterConfig,
    codec: MessageCodec,
) {
    private val scope = CoroutineScope(
        parent.coroutineContext + SupervisorJob(parent.coroutineContext.job) + config.timebase.dispatcher + CoroutineName("pod-router"),
    )
    private val lock = Any()
    private val table = RouteTable<RouteEndpoint>()
    private val targets = FrameTargets(codec)
    private val encoder = FrameEncoder(codec)
    private val started = config.timebase.clock.markNow()
    @Volatile private var onClose: () -> Unit = {}

    /** The links routed between, in the order given. */
    public val links: List<MavlinkLink> get() = ports.map { it.link }

    private fun start() {
        // Cancelling the scope the router was started in (a station closing) closes its links too.
        scope.coroutineContext.job.invokeOnCompletion { closeLinks() }
        val now = started.elapsedNow()
        synchronized(lock) {
            // A link that is not listening has its remote from the start: broadcasts reach it before it speaks.
            for (port in ports) if (!port.perPeer) port.endpointFor(RoutePort.WHOLE_LINK, now, table)
        }
        for (port in ports) {
            if (!port.fedFromOutside) {
                scope.launch(CoroutineName("route-receive(${port.link.address})")) {
                    try {
                        port.link.receive { peer, bytes -> onBytes(port, peer, bytes) }
                    } catch (e: LinkException) {
                        port.error = e.message
                    }
                }
            }
            port.outbox?.let { outbox ->
                scope.launch(CoroutineName("route-send(${port.link.address})")) {
                    for (out in outbox) {
                        try {
                            if (out.peer == null) port.link.sendToAll(out.bytes) else port.link.send(out.bytes, out.peer)
                        } catch (e: LinkException) {
                            port.error = e.message
                            port.sendDrops.incrementAndGet()
                        }
                    }
                }
            }
        }
        scope.launch(CoroutineName("route-forget")) {
            val tick = maxOf(config.forgetPeersAfter / 4, 250.milliseconds)
            while (isActive) {
                delay(tick)
                forgetSilentPeers()
            }
        }
    }

    private fun onBytes(port: RoutePort, peer: LinkPeer, bytes: ByteArray) {
        val endpoint = synchronized(lock) { port.endpointFor(port.keyOf(peer), started.elapsedNow(), table) }
        endpoint.decoder?.feed(bytes) { frame -> route(endpoint, frame, encoder.wireBytes(frame)) }
    }

    /** A frame a ground station heard from [peer] on its own link (see [forStation]). */
    internal fun fromStation(peer: LinkPeer, frame: MavFrame) {
        val port = ports.first { it.fedFromOutside }
        val endpoint = synchronized(lock) { port.endpointFor(port.keyOf(peer), started.elapsedNow(), table) }
        route(endpoint, frame, encoder.wireBytes(frame))
    }

    private fun route(source: RouteEndpoint, frame: MavFrame, bytes: ByteArray) {
        val port = source.port
        port.received.incrementAndGet()
        val targetSystem = targets.system(frame)
        val targetComponent = targets.component(frame)
        val destinations = ArrayList<RouteEndpoint>(4)
        val routed = synchronized(lock) {
            // Forgotten meanwhile (evicted or silent), it is heard again: back in the table.
            if (port.endpoints[source.peer] !== source) port.endpointFor(source.peer, started.elapsedNow(), table)
            // System id 0 is the broadcast address, never a sender's own: nothing can target it.
            if (frame.systemId != 0) table.learn(port.endpoints.getValue(source.peer), frame.systemId, frame.componentId)
            table.destinations(port.endpoints.getValue(source.peer), frame.systemId, frame.componentId, targetSystem, targetComponent, destinations)
        }
        if (!routed) port.unrouted.incrementAndGet()
        for (destination in destinations) send(destination, bytes)
    }

    private fun send(destination: RouteEndpoint, bytes: ByteArray) {
        val port = destination.port
        val link = port.link
        val peer = destination.peer.takeIf { port.perPeer }
        val outbox = port.outbox
        val sent = try {
            when {
                port.error != null -> false
                outbox != null -> outbox.trySend(Outgoing(bytes, peer)).isSuccess
                peer != null -> true.also { link.sendNow(bytes, peer) }
                else -> true.also { for (p in link.peers) link.sendNow(bytes, p) }
            }
        } catch (e: Exception) {
            false // a link closing under us: the datagram is lost, as UDP's would be
        }
        if (sent) port.forwarded.incrementAndGet() else port.sendDrops.incrementAndGet()
    }

    private fun forgetSilentPeers() {
        val now = started.elapsedNow()
        synchronized(lock) {
            for (port in ports) {
                if (!port.perPeer) continue
                val silent = port.endpoints.values.filter { now - it.lastHeard > config.forgetPeersAfter }
                for (endpoint in silent) port.forget(endpoint, table, evicting = false)
            }
        }
    }

    /** What each link counted so far, in the order of [links]. */
    public fun stats(): List<RouteLinkStats> = synchronized(lock) {
        ports.map { port -> port.stats(port.endpoints.size, port.endpoints.values.sumOf { it.decoder?.stats?.badCrc ?: 0L }) }
    }

    /** The (system shl 8 | component) ids heard on each endpoint now, by endpoint name: for tests and diagnosis. */
    internal fun routes(): Map<String, Set<Int>> = synchronized(lock) {
        table.endpoints.associate { it.toString() to table.idsOf(it).toSet() }
    }

    /** Stops routing and closes every link the router was given (not a ground station's own link). */
    public fun close() {
        scope.cancel()
        closeLinks()
    }

    private fun closeLinks() {
        ports.forEach { it.outbox?.close() }
        for (port in ports) if (!port.fedFromOutside) port.link.close()
        onClose()
    }

    /** [close]s and waits, at most [within], until the links' sockets are released. */
    public suspend fun closeAndAwait(within: Duration = 2.seconds) {
        close()
        withTimeoutOrNull(within) { for (port in ports) if (!port.fedFromOutside) port.link.awaitClosed() }
    }

    /** Starts routers. */
    public companion object {
        /**
         * Routes between [links] (at least two) from now on, in [scope]; the router owns the links
         * and closes them on [close].
         */
        public fun start(
            links: List<MavlinkLink>,
            scope: CoroutineScope,
            config: RouterConfig = RouterConfig(),
            codec: MessageCodec = MessageCodec.Default,
        ): MavlinkRouter {
            require(links.size >= 2) { "a router needs at least two links, was ${links.size}" }
            require(links.distinct().size == links.size) { "links must be distinct" }
            val ports = links.map { RoutePort(it, fedFromOutside = false, codec, config.maxPeersPerLink, config.sendQueue) }
            return MavlinkRouter(ports, scope, config, codec).also { it.start() }
        }

        /**
         * Opens [connections] (connection strings, as [MavlinkLink.open] takes) and routes between
         * them. Throws the links' typed errors; links already opened are closed again then.
         */
        public suspend fun open(
            connections: List<String>,
            scope: CoroutineScope,
            config: RouterConfig = RouterConfig(),
            codec: MessageCodec = MessageCodec.Default,
        ): MavlinkRouter {
            require(connections.size >= 2) { "a router needs at least two links, was ${connections.size}" }
            val opened = ArrayList<MavlinkLink>()
            try {
                for (connection in connections) opened += MavlinkLink.open(connection)
            } catch (e: Throwable) {
                opened.forEach { it.close() }
                throw e
            }
            return start(opened, scope, config, codec)
        }

        /**
         * A router between a ground station's own [stationLink], whose frames the station hands
         * over ([fromStation]), and [other]; [onClose] runs when it is closed.
         */
        internal fun forStation(
            stationLink: MavlinkLink,
            other: MavlinkLink,
            scope: CoroutineScope,
            config: RouterConfig,
            codec: MessageCodec,
            onClose: (MavlinkRouter) -> Unit,
        ): MavlinkRouter {
            val ports = listOf(
                RoutePort(stationLink, fedFromOutside = true, codec, config.maxPeersPerLink, config.sendQueue),
                RoutePort(other, fedFromOutside = false, codec, config.maxPeersPerLink, config.sendQueue),
            )
            return MavlinkRouter(ports, scope, config, codec).also { router ->
                router.onClose = { onClose(router) }
                router.start()
            }
        }
    }
}
