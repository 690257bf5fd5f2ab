package pod.e2e.gcs

import java.net.InetSocketAddress
import java.net.Socket
import java.util.Base64
import kotlin.random.Random

/**
 * A page that opens its WebSocket and then reads nothing, over a plain TCP socket with a small
 * receive buffer: TCP's flow control then stops the server's sends as soon as the buffers fill,
 * which a WebSocket client library, reading ahead into memory, would not.
 */
internal class StuckPage(port: Int) : AutoCloseable {
    private val socket = Socket().apply {
        receiveBufferSize = 4096
        connect(InetSocketAddress("127.0.0.1", port), 5_000)
        soTimeout = 10_000
    }

    init {
        val key = Base64.getEncoder().encodeToString(Random.nextBytes(16))
        val request = "GET /ws HTTP/1.1\r\nHost: 127.0.0.1:$port\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n" +
            "Sec-WebSocket-Key: $key\r\nSec-WebSocket-Version: 13\r\n\r\n"
        socket.getOutputStream().apply { write(request.toByteArray()); flush() }
        // The status line only: the rest stays unread, as everything after it will.
        val status = generateSequence { socket.getInputStream().read().takeIf { it >= 0 && it != '\n'.code } }.map { it.toChar() }.joinToString("")
        check(" 101 " in status) { "the WebSocket was not opened: $status" }
    }

    override fun close() = socket.close()
}
