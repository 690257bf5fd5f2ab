package pod.bench

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.runBlocking
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import java.io.File
import java.lang.management.ManagementFactory
import java.net.InetSocketAddress
import java.net.StandardSocketOptions
import java.nio.ByteBuffer
import java.nio.channels.ClosedChannelException
import java.nio.channels.DatagramChannel
import java.util.Locale
import java.util.concurrent.locks.LockSupport
import kotlin.concurrent.thread
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds


/** What the sender thread did; written by it, read by the poller after [done]. */
class SendOutcome {
    @Volatile var sent = 0L
    @Volatile var endNanos = 0L
    @Volatile var cpuNanos = 0L
    @Volatile var done = false
}

/**
 * A plain NIO sender connected to one receiver, holding every datagram pre-encoded: per system,
 * one GLOBAL_POSITION_INT for each of the 256 sequence numbers (latitude varying with it, so each
 * position differs from the last), sent in order so sequence numbers stay gap-free.
 */
class Sender(target: InetSocketAddress) : AutoCloseable {
    private val channel: DatagramChannel = DatagramChannel.open()
        .setOption(StandardSocketOptions.SO_SNDBUF, 1 shl 20)
        .bind(InetSocketAddress("127.0.0.1", 0))
        .connect(target)
    private val nextSequence = IntArray(SYSTEMS)
    private val positions = Array(SYSTEMS) { system -> Array(256) { sequence -> positionDatagram(system + 1, sequence) } }
    private val heartbeats = Array(SYSTEMS) { system -> Array(256) { sequence -> heartbeatDatagram(system + 1, sequence) } }

    /** Sends one HEARTBEAT from each system. */
    fun sendHeartbeats() {
        for (system in 0 until SYSTEMS) send(heartbeats[system][nextSequence(system)])
    }

    /**
     * Sends [count] position datagrams, round-robin over the systems, at [load] from [start], until
     * done or [deadline]; records the outcome. Pacing parks until the next datagram is due and then
     * sends all that are due, so the average rate is exact without spinning a core.
     */
    fun sendPositions(count: Int, load: OfferedLoad, start: Long, deadline: Long, outcome: SendOutcome) {
        val cpu0 = ManagementFactory.getThreadMXBean().currentThreadCpuTime
        val nanosPerDatagram = load.perSecond?.let { 1e9 / it }
        var sent = 0L
        try {
            while (sent < count) {
                if (nanosPerDatagram != null) {
                    val due = start + (sent * nanosPerDatagram).toLong()
                    val now = System.nanoTime()
                    if (now < due) {
                        LockSupport.parkNanos(due - now)
                        continue
                    }
                }
                if ((sent and 0x3FF) == 0L && System.nanoTime() > deadline) break
                val system = (sent % SYSTEMS).toInt()
                send(positions[system][nextSequence(system)])
                sent++
            }
        } finally {
            outcome.sent = sent
            outcome.endNanos = System.nanoTime()
            outcome.cpuNanos = ManagementFactory.getThreadMXBean().currentThreadCpuTime - cpu0
            outcome.done = true
        }
    }

    private fun nextSequence(system: Int): Int {
        val sequence = nextSequence[system]
        nextSequence[system] = (sequence + 1) and 0xFF
        return sequence
    }

    private fun send(datagram: ByteBuffer) {
        datagram.clear()
        channel.write(datagram)
    }

    override fun close() {
        channel.close()
    }

    private companion object {
        fun positionDatagram(systemId: Int, sequence: Int): ByteBuffer = direct(
            Fixtures.mavlink2Datagram(
                Fixtures.globalPosition(latitudeE7 = 473_977_418 + 10 * sequence, timeBootMs = 1_000L + 250L * sequence),
                systemId, Fixtures.COMPONENT_ID, sequence,
            ),
        )

        fun heartbeatDatagram(systemId: Int, sequence: Int): ByteBuffer =
            direct(Fixtures.mavlink2Datagram(Fixtures.vehicleHeartbeat(), systemId, Fixtures.COMPONENT_ID, sequence))

        fun direct(bytes: ByteArray): ByteBuffer = ByteBuffer.allocateDirect(bytes.size).put(bytes).flip()
    }
}
