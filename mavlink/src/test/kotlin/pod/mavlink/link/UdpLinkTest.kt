package pod.mavlink.link

import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.comparables.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.ConnectionState
import pod.mavlink.FleetEvent
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.codec.FrameEncoder
import java.net.InetSocketAddress
import java.nio.ByteBuffer
import java.nio.channels.DatagramChannel
import java.util.Collections
import kotlin.time.Duration.Companion.seconds

/**
 * The UDP link's receive path on real loopback sockets: a receive thread shared with the process's
 * other UDP links receives, decodes and routes (no hand-off per datagram), and goes when the last
 * link does. ([SharedReceiveTest] has many links on the shared threads.)
 */
class UdpLinkTest : StringSpec({
    val encoder = FrameEncoder()
    fun heartbeat(systemId: Int, type: MavType, sequence: Int) = encoder.encode(
        Heartbeat.builder().type(type).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
            .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_STANDBY).mavlinkVersion(3).build(),
        systemId, 1, sequence and 255,
    )
    fun receiveThreads() = Thread.getAllStackTraces().keys.filter { it.name.startsWith("pod-udp-receive") && it.isAlive }

    "every datagram is handed to onBytes on a UDP receive thread, in arrival order" {
        val link = MavlinkLink.open("udpin://127.0.0.1:0")
        val seen = Collections.synchronizedList(ArrayList<Pair<String, Int>>())
        coroutineScope {
            val receiving = launch { link.receive { _, bytes -> seen += Thread.currentThread().name to (bytes[4].toInt() and 255) } }
            DatagramChannel.open().use { sender ->
                repeat(50) { sender.send(ByteBuffer.wrap(heartbeat(1, MavType.MAV_TYPE_QUADROTOR, it)), InetSocketAddress("127.0.0.1", link.localPort)) }
            }
            withTimeout(5.seconds) { while (seen.size < 50) kotlinx.coroutines.delay(5) }
            link.close()
            withTimeout(5.seconds) { receiving.join() }
        }
        seen.map { it.first }.toSet().single() shouldStartWith "pod-udp-receive-"
        seen.map { it.second } shouldBe (0 until 50).toList()
    }

    "a station watched from another thread while datagrams from hundreds of sources arrive keeps tracking: the silent vehicle is lost, the decoders stay bounded" {
        coroutineScope {
            val config = GroundStationConfig(lostAfter = 1.seconds, streamRates = emptyMap(), requestHome = false, requestPayloads = false, maxPeers = 64)
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this, config)
            val to = InetSocketAddress("127.0.0.1", gcs.link.localPort)
            try {
                val vehicle = DatagramChannel.open().bind(InetSocketAddress("127.0.0.1", 0))
                vehicle.send(ByteBuffer.wrap(heartbeat(1, MavType.MAV_TYPE_QUADROTOR, 0)), to)
                withTimeout(5.seconds) { gcs.vehicles.first { 1 in it } }
                // 300 sources, each a socket of its own, 20 rounds: frames from strangers (a GCS heartbeat
                // of system 200, never a vehicle), interleaved with the vehicle's heartbeats, while
                // the tracking loop publishes stats from the station's dispatcher.
                val strangers = List(300) { DatagramChannel.open().bind(InetSocketAddress("127.0.0.1", 0)) }
                val stray = ByteBuffer.wrap(heartbeat(200, MavType.MAV_TYPE_GCS, 0))
                repeat(20) { round ->
                    for (s in strangers) s.send(stray.duplicate(), to)
                    vehicle.send(ByteBuffer.wrap(heartbeat(1, MavType.MAV_TYPE_QUADROTOR, round + 1)), to)
                    gcs.stats.value // read from this thread too
                }
                strangers.forEach { it.close() }
                vehicle.close()
                // The vehicle is silent now: the tracking loop must still run to notice.
                val lost = withTimeout(5.seconds) { gcs.events.filterIsInstance<FleetEvent.Lost>().first() }
                lost.vehicle.systemId shouldBe 1
                gcs.vehicles.value.getValue(1).connection.value shouldBe ConnectionState.LOST
                val stats = withTimeout(2.seconds) { gcs.stats.first { it.evictedPeers > 0 && it.unrouted > 0 } }
                stats.evictedPeers shouldBeGreaterThan 0L
                stats.trackingErrors shouldBe 0L
            } finally {
                gcs.closeAndAwait()
            }
        }
    }

    "no receive thread is left once every station opened is closed, however many were opened" {
        coroutineScope {
            repeat(200) {
                val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(streamRates = emptyMap()))
                gcs.closeAndAwait(5.seconds)
            }
        }
        withTimeout(5.seconds) { while (receiveThreads().isNotEmpty()) kotlinx.coroutines.delay(10) }
        receiveThreads().shouldBeEmpty()
    }

    "cancelling the receiver releases the socket: the port can be bound again" {
        val link = MavlinkLink.open("udpin://127.0.0.1:0")
        val port = link.localPort
        coroutineScope {
            val heard = kotlinx.coroutines.CompletableDeferred<Unit>()
            val receiving = launch { link.receive { _, _ -> heard.complete(Unit) } }
            DatagramChannel.open().use { it.send(ByteBuffer.wrap(heartbeat(1, MavType.MAV_TYPE_QUADROTOR, 0)), InetSocketAddress("127.0.0.1", port)) }
            withTimeout(5.seconds) { heard.await() }
            receiving.cancel()
            receiving.join()
        }
        link.awaitClosed()
        DatagramChannel.open().use { it.bind(InetSocketAddress("127.0.0.1", port)).localAddress }.let { (it as InetSocketAddress).port shouldBe port }
    }
})
