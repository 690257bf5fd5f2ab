package pod.mavlink.link

import io.ktor.network.sockets.BoundDatagramSocket
import io.ktor.network.sockets.Datagram
import io.ktor.network.sockets.InetSocketAddress
import io.ktor.network.sockets.aSocket
import io.ktor.network.sockets.awaitClosed
import io.ktor.utils.io.core.buildPacket
import io.ktor.utils.io.core.writeFully
import kotlinx.coroutines.channels.ClosedReceiveChannelException
import kotlinx.coroutines.channels.ClosedSendChannelException
import kotlinx.coroutines.delay
import kotlinx.io.readByteArray
import java.net.BindException
import java.net.SocketException
import java.util.concurrent.ConcurrentHashMap
import kotlin.time.Duration.Companion.milliseconds

/**
 * UDP over a Ktor datagram socket. Listening ([LinkAddress.UdpIn]) it learns a peer from every
 * datagram, so one port serves many vehicles; sending ([LinkAddress.UdpOut]) it binds an
 * ephemeral port and talks to one remote, as SITL's `--out` and pymavlink's `udpout` do.
 */
internal class UdpLink private constructor(
    override val address: LinkAddress,
    private val socket: BoundDatagramSocket,
    private val remote: LinkPeer?,
) : MavlinkLink {
    private val heard = ConcurrentHashMap<LinkPeer, Unit>()

    override val localPort: Int = (socket.localAddress as InetSocketAddress).port

    override val peers: Collection<LinkPeer>
        get() = if (remote != null) listOf(remote) else heard.keys.toList()

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        // Interning peers keeps one object per address, so callers can key state by peer cheaply.
        val interned = HashMap<io.ktor.network.sockets.SocketAddress, LinkPeer>()
        try {
            while (true) {
                val datagram = socket.incoming.receive()
                val peer = interned.getOrPut(datagram.address) {
                    LinkPeer(datagram.address).also { if (remote == null) heard[it] = Unit }
                }
                onBytes(peer, datagram.packet.readByteArray())
            }
        } catch (_: ClosedReceiveChannelException) {
            // close() was called
        }
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) {
        try {
            socket.send(Datagram(buildPacket { writeFully(bytes) }, peer.address as io.ktor.network.sockets.SocketAddress))
        } catch (e: SocketException) {
            // UDP gives no delivery guarantee anyway; a send to a vanished peer is a lost datagram.
        } catch (e: ClosedSendChannelException) {
            // close() was called: nothing more goes out.
        }
    }

    override fun close() {
        socket.close()
    }

    override suspend fun awaitClosed() {
        socket.awaitClosed()
        // Java NIO keeps a closed channel's socket open while it is still registered with a selector
        // (it is released when the selector next deregisters it, on Ktor's selector thread): a
        // listening link waits until its port can be bound again. An ephemeral port nobody asks for.
        val listening = address as? LinkAddress.UdpIn ?: return
        if (listening.port == 0) return
        val port = java.net.InetSocketAddress(listening.host, localPort)
        while (true) {
            try {
                java.net.DatagramSocket(port).close()
                return
            } catch (_: SocketException) {
                delay(RELEASE_POLL)
            }
        }
    }

    companion object {
        /** Big enough for a burst from dozens of vehicles; Linux caps it at net.core.rmem_max. */
        const val RECEIVE_BUFFER_BYTES = 4 shl 20

        /** How often [awaitClosed] looks whether the port is free again. */
        private val RELEASE_POLL = 5.milliseconds

        suspend fun open(address: LinkAddress): UdpLink {
            val remote = if (address is LinkAddress.UdpOut) {
                val resolved = java.net.InetSocketAddress(address.host, address.port)
                if (resolved.isUnresolved) throw HostUnreachable(address, "unknown host '${address.host}'")
                LinkPeer(InetSocketAddress(address.host, address.port))
            } else {
                null
            }
            val local = if (address is LinkAddress.UdpIn) InetSocketAddress(address.host, address.port) else null
            val socket = try {
                aSocket(Selectors.shared).udp().bind(local) {
                    receiveBufferSize = RECEIVE_BUFFER_BYTES
                    sendBufferSize = 1 shl 20
                }
            } catch (e: BindException) {
                if (e.message.orEmpty().contains("in use", ignoreCase = true)) throw PortInUse(address, e)
                throw LinkException("cannot listen on ${address.hostAndPort}: ${e.message}", e)
            } catch (e: java.nio.channels.UnresolvedAddressException) {
                throw HostUnreachable(address, "unknown host '${address.host}'", e)
            }
            return UdpLink(address, socket, remote)
        }
    }
}
