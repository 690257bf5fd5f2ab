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


/** A receiver under test, bound to an ephemeral loopback port. */
interface Receiver : AutoCloseable {
    val address: InetSocketAddress

    /** Makes the receiver ready for the position stream (Pod needs the vehicles' HEARTBEATs first). */
    fun announce(sender: Sender) {}

    /** Position datagrams processed so far. */
    fun processed(): Long

    /** Frames the receiver itself counted as lost, when it can tell. */
    fun gapLoss(): Long? = null
}

/**
 * A Pod ground station on `udpin://127.0.0.1:0`. A datagram counts as processed once the station
 * decoded it and routed it into a vehicle's telemetry (its `linkQuality.received`).
 */
class PodReceiver private constructor(
    private val scope: CoroutineScope,
    private val station: GroundStation,
) : Receiver {
    private var baselineReceived = 0L
    private var baselineLost = 0L

    override val address: InetSocketAddress = InetSocketAddress("127.0.0.1", station.link.localPort)

    override fun announce(sender: Sender) {
        // HEARTBEATs until all vehicles exist, bounded; the station only routes frames of systems it knows.
        val deadline = System.nanoTime() + ANNOUNCE_LIMIT.inWholeNanoseconds
        while (station.vehicles.value.size < SYSTEMS) {
            check(System.nanoTime() < deadline) {
                "Pod found ${station.vehicles.value.size} of $SYSTEMS vehicles within $ANNOUNCE_LIMIT (stats ${station.stats.value})"
            }
            sender.sendHeartbeats()
            Thread.sleep(50)
        }
        // Let late duplicate HEARTBEATs land before taking the baseline.
        Thread.sleep(200)
        baselineReceived = sumReceived()
        baselineLost = sumLost()
    }

    override fun processed(): Long = sumReceived() - baselineReceived

    override fun gapLoss(): Long = sumLost() - baselineLost

    private fun sumReceived(): Long = station.vehicles.value.values.sumOf { it.telemetry.linkQuality.value.received }

    private fun sumLost(): Long = station.vehicles.value.values.sumOf { it.telemetry.linkQuality.value.lost }

    override fun close() {
        station.close()
        scope.cancel()
    }

    companion object {
        private val ANNOUNCE_LIMIT = 5.seconds

        /** Opens a station that asks for no streams and never marks a vehicle lost during a run. */
        fun open(): PodReceiver {
            val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
            val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, lostAfter = 10.minutes)
            val station = runBlocking { GroundStation.open("udpin://127.0.0.1:0", scope, config) }
            return PodReceiver(scope, station)
        }
    }
}

/** The floor: a blocking NIO receive loop on its own thread that only counts datagrams. */
class NioReceiver : Receiver {
    private val channel: DatagramChannel = DatagramChannel.open()
        .setOption(StandardSocketOptions.SO_RCVBUF, RECEIVE_BUFFER_BYTES)
        .bind(InetSocketAddress("127.0.0.1", 0))

    // One writer (the receive thread), read by the poller: a volatile plain counter is enough.
    @Volatile private var count = 0L

    private val receiving = thread(name = "nio-receiver", isDaemon = true) {
        val buffer = ByteBuffer.allocateDirect(2048)
        try {
            while (true) {
                buffer.clear()
                channel.receive(buffer)
                count++
            }
        } catch (_: ClosedChannelException) {
            // close() ends the loop
        }
    }

    override val address: InetSocketAddress = channel.localAddress as InetSocketAddress

    override fun processed(): Long = count

    override fun close() {
        channel.close()
        receiving.join(1_000)
    }
}
