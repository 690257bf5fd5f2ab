package pod.mavlink.link

import io.ktor.network.sockets.InetSocketAddress
import io.ktor.network.sockets.Socket
import io.ktor.network.sockets.aSocket
import io.ktor.network.sockets.awaitClosed
import io.ktor.network.sockets.openReadChannel
import io.ktor.network.sockets.openWriteChannel
import io.ktor.utils.io.ByteWriteChannel
import io.ktor.utils.io.readAvailable
import io.ktor.utils.io.writeFully
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import java.io.IOException
import java.net.ConnectException

/** A TCP client link to one server (SITL's TCP port, a MAVLink router). */
internal class TcpLink private constructor(
    override val address: LinkAddress,
    private val socket: Socket,
) : MavlinkLink {
    private val remote = LinkPeer(socket.remoteAddress)
    private val output: ByteWriteChannel = socket.openWriteChannel(autoFlush = false)
    private val writing = Mutex()

    @Volatile private var closed = false

    override val localPort: Int = (socket.localAddress as InetSocketAddress).port

    override val peers: Collection<LinkPeer> = listOf(remote)

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        val input = socket.openReadChannel()
        val buffer = ByteArray(4096)
        while (true) {
            val n = try {
                input.readAvailable(buffer, 0, buffer.size)
            } catch (e: IOException) {
                if (closed) return
                throw LinkException("tcp link to ${address.hostAndPort} broke: ${e.message}", e)
            }
            if (n < 0) {
                if (closed) return
                throw LinkException("tcp link to ${address.hostAndPort} was closed by the remote")
            }
            if (n > 0) onBytes(remote, buffer.copyOf(n))
        }
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) {
        if (closed) return
        writing.withLock {
            try {
                output.writeFully(bytes)
                output.flush()
            } catch (e: IOException) {
                if (!closed) throw LinkException("tcp link to ${address.hostAndPort} broke: ${e.message}", e)
            }
        }
    }

    override fun close() {
        closed = true
        socket.close()
    }

    // Ktor closes the channel on its selector after close() returns; the socket's job ends once it has.
    override suspend fun awaitClosed() {
        socket.awaitClosed()
    }

    companion object {
        suspend fun open(address: LinkAddress): TcpLink {
            val resolved = java.net.InetSocketAddress(address.host, address.port)
            if (resolved.isUnresolved) throw HostUnreachable(address, "unknown host '${address.host}'")
            try {
                val socket = aSocket(Selectors.shared).tcp().connect(address.host, address.port)
                return TcpLink(address, socket)
            } catch (e: ConnectException) {
                throw HostUnreachable(address, e.message ?: "connection refused", e)
            }
        }
    }
}
