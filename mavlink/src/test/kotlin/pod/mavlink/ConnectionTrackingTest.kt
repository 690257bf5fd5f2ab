package pod.mavlink

import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeGreaterThan
import io.kotest.matchers.comparables.shouldBeLessThanOrEqualTo
import io.kotest.matchers.shouldBe
import io.ktor.network.sockets.InetSocketAddress
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.yield
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink

/**
 * A link that delivers what a test scripts, from as many source addresses as it likes, on the
 * station's receive coroutine; nothing goes on a network.
 */
private class ScriptedLink(private val script: suspend ((LinkPeer, ByteArray) -> Unit) -> Unit) : MavlinkLink {
    override val address: LinkAddress = LinkAddress.parse("udpin://127.0.0.1:0")
    override val localPort: Int = 0
    override val peers: Collection<LinkPeer> = emptyList()

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        script(onBytes)
        awaitCancellation()
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) = Unit

    override fun close() = Unit
}

private fun peer(i: Int) = LinkPeer(InetSocketAddress("127.${(i shr 16) and 255}.${(i shr 8) and 255}.${i and 255}", 14550))

class ConnectionTrackingTest : StringSpec({
    val encoder = FrameEncoder()
    fun heartbeat(sequence: Int) = copterHeartbeat(1, sequence)

    "datagrams from many new addresses while stats are published: the decoders stay bounded and a vehicle that then falls silent is still marked lost" {
        coroutineScope {
            val vehicle = peer(1)
            val flooded = CompletableDeferred<Unit>()
            // A frame from an address that never sent a HEARTBEAT: decoded, counted, not routed.
            val stray = encoder.encode(Heartbeat.builder().type(MavType.MAV_TYPE_GCS).autopilot(MavAutopilot.MAV_AUTOPILOT_INVALID).build(), 200, 1, 0)
            val link = ScriptedLink { deliver ->
                deliver(vehicle, heartbeat(0))
                // Two seconds of new source addresses, interleaved with the vehicle's heartbeats,
                // while the tracking loop publishes stats four times a second.
                val start = kotlin.time.TimeSource.Monotonic.markNow()
                var i = 2
                while (start.elapsedNow() < 2.seconds) {
                    repeat(500) { deliver(peer(i++), stray) }
                    deliver(vehicle, heartbeat(i))
                    yield()
                }
                flooded.complete(Unit)
            }
            val config = GroundStationConfig(lostAfter = 1.seconds, streamRates = emptyMap(), requestHome = false, requestPayloads = false, maxPeers = 256)
            val gcs = GroundStation.open(link, this, config)
            try {
                withTimeout(5.seconds) { flooded.await() }
                val found = gcs.vehicles.value.getValue(1)
                found.connection.value shouldBe pod.core.vehicle.ConnectionState.CONNECTED
                // The vehicle is now silent: the tracking loop must still be running to notice.
                val lost = withTimeout(5.seconds) { gcs.events.filterIsInstance<FleetEvent.Lost>().first() }
                lost.vehicle.systemId shouldBe 1
                val stats = withTimeout(2.seconds) { gcs.stats.first { it.evictedPeers > 0 } }
                stats.evictedPeers shouldBeGreaterThan 1000L
                stats.frames shouldBeGreaterThan 1000L
                gcs.peerCount shouldBeLessThanOrEqualTo 256
            } finally {
                gcs.close()
            }
        }
    }

    "a peer heard again keeps its decoder while the flood evicts the others" {
        val decoders = PeerDecoders(4, pod.mavlink.codec.MessageCodec.Default)
        val kept = decoders.decoderFor(peer(1))
        for (i in 2..50) {
            decoders.decoderFor(peer(i))
            decoders.decoderFor(peer(1)) shouldBe kept
        }
        decoders.size shouldBe 4
        decoders.totals().evictions shouldBe 46L
    }

    "silence is measured on the station's clock (GroundStationConfig.clock): a vehicle is lost when that clock says so" {
        coroutineScope {
            val clock = kotlin.time.TestTimeSource()
            val link = ScriptedLink { deliver -> deliver(peer(1), heartbeat(0)) }
            val config = GroundStationConfig(lostAfter = 1.hours, streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = pod.core.time.Timebase(clock, kotlinx.coroutines.Dispatchers.Default))
            val gcs = GroundStation.open(link, this, config)
            try {
                val found = withTimeout(5.seconds) { gcs.vehicles.first { 1 in it } }.getValue(1)
                found.connection.value shouldBe pod.core.vehicle.ConnectionState.CONNECTED
                // An hour of this clock passes; on the wall clock, no time to speak of.
                clock += 2.hours
                withTimeout(5.seconds) { found.connection.first { it == pod.core.vehicle.ConnectionState.LOST } }
                found.lastHeartbeat.elapsedNow() shouldBeGreaterThan 1.hours
            } finally {
                gcs.close()
            }
        }
    }

    "a vehicle is published with its first heartbeat applied: whoever sees it in vehicles reads it armed, never a default" {
        val armed = encoder.encode(
            Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
                .baseMode(EnumValue.create(128)).customMode(4).systemStatus(MavState.MAV_STATE_ACTIVE).mavlinkVersion(3).build(),
            1, 1, 0,
        )
        repeat(50) {
            coroutineScope {
                val go = CompletableDeferred<Unit>()
                val link = ScriptedLink { deliver -> go.await(); deliver(peer(1), armed) }
                val gcs = GroundStation.open(link, this, GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false))
                try {
                    // Another thread looks at the fleet as closely as it can, as a command picking its vehicle does.
                    val seen = async(kotlinx.coroutines.Dispatchers.Default) {
                        var vehicles = gcs.vehicles.value
                        go.complete(Unit)
                        while (1 !in vehicles) vehicles = gcs.vehicles.value
                        vehicles.getValue(1).telemetry.armed.value
                    }
                    withTimeout(5.seconds) { seen.await() } shouldBe true
                } finally {
                    gcs.close()
                }
            }
        }
    }
})
