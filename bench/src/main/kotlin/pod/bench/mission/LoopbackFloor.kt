package pod.bench.mission

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.runInterruptible
import pod.bench.Fixtures
import pod.bench.percentile
import pod.sim.fault.LossyRelay
import java.net.DatagramPacket
import java.net.DatagramSocket
import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.SocketException
import java.net.SocketTimeoutException
import kotlin.concurrent.thread

/** Round trips of one small datagram: [samples] measured, [lost] that never came back within a second. */
data class Floor(val path: String, val samples: List<Double>, val lost: Int) {
    val medianMs: Double get() = percentile(samples, 50.0)
    val p99Ms: Double get() = percentile(samples, 99.0)
}

/**
 * The floor under every transfer: ping-pong of a HEARTBEAT frame through a [LossyRelay] with no
 * faults (the same relay code every transfer crosses), one datagram in flight at a time. Also,
 * for scale, the same ping-pong straight between two sockets.
 */
suspend fun measureFloor(warmUp: Int, samples: Int): List<Floor> = coroutineScope {
    Echo().use { echo ->
        val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:${echo.port}", seed = 0)
        relay.start(this)
        try {
            listOf(
                runInterruptible(Dispatchers.IO) { pingPong("through LossyRelay (no faults)", relay.portA, warmUp, samples) },
                runInterruptible(Dispatchers.IO) { pingPong("direct socket to socket", echo.port, warmUp, samples) },
            )
        } finally {
            relay.close()
            coroutineContext.cancelChildren()
        }
    }
}

/** Sends every datagram it receives back where it came from, on its own thread, until closed. */
private class Echo : AutoCloseable {
    private val socket = DatagramSocket(InetSocketAddress(InetAddress.getLoopbackAddress(), 0))
    val port: Int = socket.localPort

    init {
        thread(isDaemon = true, name = "floor-echo") {
            val packet = DatagramPacket(ByteArray(2048), 2048)
            try {
                while (true) {
                    packet.setLength(2048)
                    socket.receive(packet)
                    socket.send(DatagramPacket(packet.data, packet.length, packet.socketAddress))
                }
            } catch (_: SocketException) {
                // Closed.
            }
        }
    }

    override fun close() = socket.close()
}

private fun pingPong(path: String, port: Int, warmUp: Int, samples: Int): Floor {
    // The MAVLink sequence byte tells a late reply to an earlier ping from the answer to this one.
    val frames = List(256) { Fixtures.mavlink2Datagram(Fixtures.vehicleHeartbeat(), VEHICLE_SYSTEM_ID, 1, it) }
    val target = InetSocketAddress(InetAddress.getLoopbackAddress(), port)
    val rtts = ArrayList<Double>(samples)
    var lost = 0
    DatagramSocket(InetSocketAddress(InetAddress.getLoopbackAddress(), 0)).use { socket ->
        socket.soTimeout = 1000
        val reply = DatagramPacket(ByteArray(2048), 2048)
        for (i in 0 until warmUp + samples) {
            val frame = frames[i and 0xFF]
            val start = System.nanoTime()
            socket.send(DatagramPacket(frame, frame.size, target))
            var answered = false
            try {
                // Bounded: each receive waits at most a second, and stale replies are few.
                var tries = 0
                while (!answered && tries++ < 4) {
                    reply.setLength(2048)
                    socket.receive(reply)
                    answered = reply.length == frame.size && reply.data[4] == frame[4]
                }
            } catch (_: SocketTimeoutException) {
            }
            val ms = (System.nanoTime() - start) / 1e6
            if (i < warmUp) continue
            if (answered) rtts += ms else lost++
        }
    }
    return Floor(path, rtts, lost)
}
