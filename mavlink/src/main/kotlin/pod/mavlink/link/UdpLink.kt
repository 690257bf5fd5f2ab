package pod.mavlink.link

import io.ktor.network.sockets.InetSocketAddress
import io.ktor.network.sockets.toJavaAddress
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.asCoroutineDispatcher
import kotlinx.coroutines.runInterruptible
import java.io.IOException
import java.net.BindException
import java.net.PortUnreachableException
import java.net.SocketAddress
import java.net.StandardSocketOptions
import java.nio.ByteBuffer
import java.nio.channels.ClosedChannelException
import java.nio.channels.DatagramChannel
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.Executors

/**
 * UDP over a java.nio [DatagramChannel]. Listening ([LinkAddress.UdpIn]) it learns a peer from
 * every datagram, so one port serves many vehicles; sending ([LinkAddress.UdpOut]) it binds an
 * ephemeral port and talks to one remote, as SITL's `--out` and pymavlink's `udpout` do.
 *
 * [receive] runs on a thread of the link's own, started for the call and ended with it: it blocks
 * in `receive(2)` and calls `onBytes` in place, so a datagram is read, decoded, routed and applied
 * to telemetry on one thread, with no hand-off. Ktor 3.6.1's datagram socket cannot do that: its
 * receiver is a `produce(Dispatchers.IO)` coroutine feeding a channel whatever selector it is
 * given, and its `send` takes a mutex and hops to Dispatchers.IO (BENCHMARKS.md, issue 13).
 * [send] writes from the caller's thread: a UDP `sendto` does not wait for the peer.
 */
internal class UdpLink private constructor(
    override val address: LinkAddress,
    private val channel: DatagramChannel,
    private val remote: LinkPeer?,
    private val remoteAddress: SocketAddress?,
) : MavlinkLink {
    // Peer → its java address, for send; when listening, also the set [peers] reports.
    private val heard = ConcurrentHashMap<LinkPeer, SocketAddress>()
    private val receiveEnded = CompletableDeferred<Unit>()
    @Volatile private var receiveStarted = false

    override val localPort: Int = (channel.localAddress as java.net.InetSocketAddress).port

    override val peers: Collection<LinkPeer>
        get() = if (remote != null) listOf(remote) else heard.keys.toList()

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        receiveStarted = true
        val thread = Executors.newSingleThreadExecutor { task ->
            Thread(task, "pod-udp-receive-$localPort").apply { isDaemon = true }
        }
        try {
            // Cancelling the caller interrupts the thread, which closes the channel (NIO's rule for
            // an interrupted blocking read): a station whose scope is cancelled releases its port.
            runInterruptible(thread.asCoroutineDispatcher()) { receiveLoop(onBytes) }
        } finally {
            thread.shutdown()
            receiveEnded.complete(Unit)
        }
    }

    private fun receiveLoop(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        // Interning peers keeps one object per address, so callers can key state by peer cheaply;
        // this map is the receive thread's alone.
        val interned = HashMap<SocketAddress, LinkPeer>()
        val buffer = ByteBuffer.allocateDirect(MAX_DATAGRAM)
        while (true) {
            buffer.clear()
            val from = try {
                channel.receive(buffer) ?: continue
            } catch (_: ClosedChannelException) {
                return // close() was called, or the caller was cancelled
            } catch (_: PortUnreachableException) {
                continue // an ICMP error for an earlier send: that datagram was lost, nothing more
            } catch (e: IOException) {
                if (!channel.isOpen) return
                throw LinkException("udp link on ${address.hostAndPort} broke: ${e.message}", e)
            }
            buffer.flip()
            val bytes = ByteArray(buffer.remaining())
            buffer.get(bytes)
            val peer = interned.getOrPut(from) {
                LinkPeer(from.asKtorAddress()).also { if (remote == null) heard[it] = from }
            }
            onBytes(peer, bytes)
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
        // Returns once a receive blocked on the channel has left it and the socket is released.
        channel.close()
    }

    override suspend fun awaitClosed() {
        // close() released the socket already (the channel is registered with no selector); what is
        // left is the receive thread's way out, so that a closed link holds no thread either.
        if (!channel.isOpen && receiveStarted) receiveEnded.await()
    }

    companion object {
        /** Big enough for a burst from dozens of vehicles; Linux caps it at net.core.rmem_max. */
        const val RECEIVE_BUFFER_BYTES = 4 shl 20

        /** The largest UDP payload; MAVLink frames are at most 280 bytes, but a datagram may carry several. */
        private const val MAX_DATAGRAM = 65_507

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

// Peers carry Ktor addresses, as every link's peers do (LinkPeer.address); made once per new sender.
private fun SocketAddress.asKtorAddress(): InetSocketAddress {
    val inet = this as java.net.InetSocketAddress
    return InetSocketAddress(inet.address.address, inet.port)
}
