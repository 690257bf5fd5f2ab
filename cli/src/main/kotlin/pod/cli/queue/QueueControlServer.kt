package pod.cli.queue

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.ensureActive
import kotlinx.coroutines.launch
import kotlinx.coroutines.runInterruptible
import kotlinx.serialization.SerializationException
import java.io.IOException
import java.io.Reader
import java.net.BindException
import java.nio.channels.Channels
import java.nio.channels.ClosedChannelException
import java.nio.channels.ServerSocketChannel
import java.nio.channels.SocketChannel

/**
 * The host side of the control protocol ([QueueProtocol]): a TCP server on a loopback address that
 * reads [QueueRequest] lines and writes the [QueueResponse] lines an answering function returns.
 *
 * Blocking NIO channels on the IO dispatcher, one coroutine per connection: channels are
 * interruptible, so cancelling [serve] interrupts the blocked threads, which closes the channels
 * and frees the port. Bind with [bind] before the vehicle is looked for, so that a port in use is
 * said at once.
 */
internal class QueueControlServer private constructor(private val channel: ServerSocketChannel, val address: ControlAddress) : AutoCloseable {
    /** Answers connections until cancelled, then lets the port go; [answer] is called on IO threads, concurrently. */
    suspend fun serve(answer: (QueueRequest) -> QueueResponse): Nothing = try {
        accepting(answer)
    } finally {
        // A cancellation that comes between two accepts interrupts no blocked thread: close here.
        channel.close()
    }

    private suspend fun accepting(answer: (QueueRequest) -> QueueResponse): Nothing = coroutineScope {
        while (true) {
            val connection = try {
                runInterruptible(Dispatchers.IO) { channel.accept() }
            } catch (e: ClosedChannelException) {
                // Interrupted by our own cancellation (the channel closes with it): say cancelled, not broken.
                currentCoroutineContext().ensureActive()
                throw e
            }
            launch(Dispatchers.IO) { connection.use { converse(it, answer) } }
        }
        @Suppress("UNREACHABLE_CODE")
        error("unreachable")
    }

    private suspend fun converse(connection: SocketChannel, answer: (QueueRequest) -> QueueResponse) {
        val reader = Channels.newReader(connection, Charsets.UTF_8).buffered()
        val writer = Channels.newWriter(connection, Charsets.UTF_8).buffered()
        try {
            while (true) {
                val line = runInterruptible { readLine(reader) } ?: return
                if (line.isBlank()) continue
                val response = try {
                    answer(QueueProtocol.decodeRequest(line))
                } catch (e: SerializationException) {
                    QueueResponse(ok = false, error = "not a queue request: ${e.message?.lineSequence()?.first()}")
                } catch (e: IllegalArgumentException) {
                    QueueResponse(ok = false, error = e.message ?: "bad request")
                }
                runInterruptible {
                    writer.write(QueueProtocol.encode(response))
                    writer.write("\n")
                    writer.flush()
                }
            }
        } catch (e: IOException) {
            // The client went away, or sent a line too long to read: its connection ends, the host goes on.
        }
    }

    override fun close() {
        channel.close()
    }

    companion object {
        /** Listens on [address]; throws [IllegalArgumentException] with a message for people when it cannot. */
        fun bind(address: ControlAddress): QueueControlServer {
            val channel = ServerSocketChannel.open()
            try {
                channel.bind(address.socketAddress)
            } catch (e: BindException) {
                channel.close()
                val why = if (e.message.orEmpty().contains("in use", ignoreCase = true)) "the port is already in use (another `pod queue serve`? pick another port with --control)" else e.message
                throw IllegalArgumentException("cannot listen on $address: $why", e)
            } catch (e: IOException) {
                channel.close()
                throw IllegalArgumentException("cannot listen on $address: ${e.message}", e)
            }
            val port = (channel.localAddress as java.net.InetSocketAddress).port
            return QueueControlServer(channel, address.copy(port = port))
        }

        /** One line from [reader] without its end, or null at the end of the stream; a line over [QueueProtocol.MAX_LINE] is an [IOException]. */
        internal fun readLine(reader: Reader): String? {
            val line = StringBuilder()
            while (true) {
                val c = reader.read()
                when {
                    c < 0 -> return if (line.isEmpty()) null else line.toString()
                    c == '\n'.code -> return line.toString().removeSuffix("\r")
                    line.length >= QueueProtocol.MAX_LINE -> throw IOException("a line over ${QueueProtocol.MAX_LINE} characters")
                    else -> line.append(c.toChar())
                }
            }
        }
    }
}
