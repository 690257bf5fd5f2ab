package pod.mavlink.link

import io.ktor.network.sockets.InetSocketAddress
import io.ktor.network.sockets.Socket
import io.ktor.network.sockets.aSocket
import io.ktor.network.sockets.awaitClosed
import io.ktor.network.sockets.openReadChannel
import io.ktor.network.sockets.openWriteChannel
import io.ktor.utils.io.ByteReadChannel
import io.ktor.utils.io.ByteWriteChannel
import io.ktor.utils.io.readAvailable
import io.ktor.utils.io.writeFully
import java.net.ConnectException

/**
 * A TCP client link to one server (SITL's TCP port, a MAVLink router): a [StreamLink] over a Ktor
 * socket. A server that hangs up ends the link ([LinkException] from receive and send); it is not
 * reconnected.
 */
internal object TcpLink {
    suspend fun open(address: LinkAddress): ByteStreamLink {
        val resolved = java.net.InetSocketAddress(address.host, address.port)
        if (resolved.isUnresolved) throw HostUnreachable(address, "unknown host '${address.host}'")
        val socket = try {
            aSocket(Selectors.shared).tcp().connect(address.host, address.port)
        } catch (e: ConnectException) {
            throw HostUnreachable(address, e.message ?: "connection refused", e)
        }
        return StreamLink(
            address, name = "tcp link to ${address.hostAndPort}", endedReason = "was closed by the remote",
            first = TcpStream(socket), remote = socket.remoteAddress,
            localPort = (socket.localAddress as InetSocketAddress).port, reopening = null,
        )
    }
}

/** A connected Ktor socket as a [ByteStream]: it suspends on Ktor's selector, holding no thread. */
private class TcpStream(private val socket: Socket) : ByteStream {
    private val input: ByteReadChannel = socket.openReadChannel()
    private val output: ByteWriteChannel = socket.openWriteChannel(autoFlush = false)

    override suspend fun read(buffer: ByteArray): Int = input.readAvailable(buffer, 0, buffer.size)

    override suspend fun write(bytes: ByteArray): Int {
        output.writeFully(bytes)
        output.flush()
        return bytes.size
    }

    override fun close() {
        socket.close()
    }

    // Ktor closes the channel on its selector after close() returns; the socket's job ends once it has.
    override suspend fun awaitClosed() {
        socket.awaitClosed()
    }
}
