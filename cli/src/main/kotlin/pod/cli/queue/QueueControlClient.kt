package pod.cli.queue

import kotlinx.serialization.SerializationException
import pod.core.PodException
import java.io.IOException
import java.net.ConnectException
import java.net.Socket
import java.net.SocketTimeoutException

/**
 * The client side of the control protocol: one request, one answer, on a connection of its own.
 * Blocking, for one-shot commands; the host answers at once (it only changes the queue it holds),
 * so a long wait means a host that is stuck, said after [answerTimeoutMs].
 */
internal class QueueControlClient(
    private val address: ControlAddress,
    private val connectTimeoutMs: Int = 3_000,
    private val answerTimeoutMs: Int = 10_000,
) {
    /** Sends [request] and returns the host's answer; throws [NoQueueHost] or [QueueHostFailed]. */
    fun ask(request: QueueRequest): QueueResponse {
        val socket = Socket()
        try {
            try {
                socket.connect(address.socketAddress, connectTimeoutMs)
            } catch (e: ConnectException) {
                throw NoQueueHost(address, e.message ?: "connection refused")
            } catch (e: SocketTimeoutException) {
                throw NoQueueHost(address, "no answer to the connection within $connectTimeoutMs ms")
            }
            socket.soTimeout = answerTimeoutMs
            val writer = socket.getOutputStream().bufferedWriter(Charsets.UTF_8)
            writer.write(QueueProtocol.encode(request))
            writer.write("\n")
            writer.flush()
            val line = QueueControlServer.readLine(socket.getInputStream().bufferedReader(Charsets.UTF_8))
                ?: throw QueueHostFailed(address, "it closed the connection without answering")
            return try {
                QueueProtocol.decodeResponse(line)
            } catch (e: SerializationException) {
                throw QueueHostFailed(address, "its answer is not a queue response: ${line.take(200)}")
            }
        } catch (e: SocketTimeoutException) {
            throw QueueHostFailed(address, "no answer within ${answerTimeoutMs / 1000} s")
        } catch (e: IOException) {
            throw QueueHostFailed(address, e.message ?: e.toString())
        } finally {
            socket.close()
        }
    }
}

/** Nothing listens on [address]: no `pod queue serve` runs there. */
internal class NoQueueHost(val address: ControlAddress, reason: String) :
    PodException("no `pod queue serve` answers on $address ($reason): start one with `pod queue serve --connect LINK`, or name its address with --control")

/** The host at [address] was reached but did not answer properly. */
internal class QueueHostFailed(val address: ControlAddress, reason: String) : PodException("the queue host on $address failed: $reason")
