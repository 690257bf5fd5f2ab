package pod.mavlink.link

import io.ktor.network.sockets.InetSocketAddress
import io.ktor.network.sockets.toJavaAddress
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.withContext
import java.io.IOException
import java.net.BindException
import java.net.SocketAddress
import java.net.StandardSocketOptions
import java.nio.ByteBuffer
import java.nio.channels.DatagramChannel
import java.util.concurrent.ConcurrentHashMap

/**
 * UDP over a java.nio [DatagramChannel]. Listening ([LinkAddress.UdpIn]) it learns a peer from
 * every datagram, so one port serves many vehicles; sending ([LinkAddress.UdpOut]) it binds an
 * ephemeral port and talks to one remote, as SITL's `--out` and pymavlink's `udpout` do.
 *
 * [receive] registers the channel with one of the process's UDP receive loops ([UdpReceiveLoop]:
 * one selector thread each, one per core at most), which reads it and calls `onBytes` in place, so
 * a datagram is read, decoded, routed and applied to telemetry on one thread, with no hand-off, and
 * hundreds of links in one process (a simulated fleet, `pod route`) share a few threads. Ktor
 * 3.6.1's datagram socket cannot do that: its receiver is a `produce(Dispatchers.IO)` coroutine
 * feeding a channel whatever selector it is given, and its `send` takes a mutex and hops to
 * Dispatchers.IO (BENCHMARKS.md, issue 13). [send] writes from the caller's thread: a UDP `sendto`
 * does not wait for the peer (the channel is non-blocking, as a selector needs: a datagram that
 * finds the socket's send buffer full is dropped, as a full router queue would drop it).
 */
internal class UdpLink private constructor(
    override val address: LinkAddress,
    private val channel: DatagramChannel,
    private val remote: LinkPeer?,
    private val remoteAddress: SocketAddress?,
) : MavlinkLink {
    // Peer → its java address, for send; when listening, also the set [peers] reports.
    private val heard = ConcurrentHashMap<LinkPeer, SocketAddress>()
    private val lock = Any()
    @Volatile private var receiver: UdpReceiver? = null
    private var loop: UdpReceiveLoop? = null // guarded by lock

    override val localPort: Int = (channel.localAddress as java.net.InetSocketAddress).port

    override val peers: Collection<LinkPeer>
        get() = if (remote != null) listOf(remote) else heard.keys.toList()

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        val receiver = UdpReceiver(channel, address.hostAndPort, onBytes) { from, peer -> if (remote == null) heard[peer] = from }
        // Under the lock with close(), so that a loop is told of a closing only after it was given the receiver.
        synchronized(lock) {
            if (!channel.isOpen) return
            val loop = Selectors.udp.pick()
            this.loop = loop
            this.receiver = receiver
            loop.add(receiver)
        }
        try {
            receiver.ended.await()
        } catch (e: CancellationException) {
            // A cancelled receiver closes its link, as a blocking read interrupted does in NIO: a
            // station whose scope is cancelled releases its port. Returns once the loop let go.
            close()
            withContext(NonCancellable) { receiver.ended.join() }
            throw e
        }
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) = sendNow(bytes, peer)

    override val sendsInPlace: Boolean get() = true

    override fun sendNow(bytes: ByteArray, peer: LinkPeer) {
        val to = if (peer == remote) remoteAddress else heard[peer] ?: (peer.address as? io.ktor.network.sockets.SocketAddress)?.toJavaAddress()
        try {
            channel.send(ByteBuffer.wrap(bytes), to ?: return)
        } catch (_: IOException) {
            // UDP gives no delivery guarantee anyway: a send to a vanished peer, or after close(), is a
            // lost datagram.
        }
    }

    override fun close() {
        // A registered channel's socket is released when the loop drops its registration: see awaitClosed.
        synchronized(lock) {
            channel.close()
            receiver?.let { loop?.remove(it) }
        }
    }

    override suspend fun awaitClosed() {
        // The receive loop completes `ended` once the selector dropped the channel, which is when
        // NIO closes a registered channel's socket; a link never received on was released by close().
        if (!channel.isOpen) receiver?.ended?.join()
    }

    companion object {
        /** Big enough for a burst from dozens of vehicles; Linux caps it at net.core.rmem_max. */
        const val RECEIVE_BUFFER_BYTES = 4 shl 20

        fun open(address: LinkAddress): UdpLink {
            val remoteAddress = if (address is LinkAddress.UdpOut) {
                val resolved = java.net.InetSocketAddress(address.host, address.port)
                if (resolved.isUnresolved) throw HostUnreachable(address, "unknown host '${address.host}'")
                resolved
            } else {
                null
            }
            val remote = remoteAddress?.let { LinkPeer(InetSocketAddress(address.host, address.port)) }
            val local = if (address is LinkAddress.UdpIn) java.net.InetSocketAddress(address.host, address.port) else null
            val channel = DatagramChannel.open()
            try {
                channel.setOption(StandardSocketOptions.SO_RCVBUF, RECEIVE_BUFFER_BYTES)
                channel.setOption(StandardSocketOptions.SO_SNDBUF, 1 shl 20)
                channel.bind(local)
                channel.configureBlocking(false)
            } catch (e: BindException) {
                channel.close()
                if (e.message.orEmpty().contains("in use", ignoreCase = true)) throw PortInUse(address, e)
                throw LinkException("cannot listen on ${address.hostAndPort}: ${e.message}", e)
            } catch (e: java.nio.channels.UnresolvedAddressException) {
                channel.close()
                throw HostUnreachable(address, "unknown host '${address.host}'", e)
            }
            return UdpLink(address, channel, remote, remoteAddress)
        }
    }
}
