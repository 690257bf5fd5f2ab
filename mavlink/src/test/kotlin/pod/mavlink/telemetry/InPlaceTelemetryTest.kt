package pod.mavlink.telemetry

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.runTest
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.copterHeartbeat
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import pod.mavlink.virtualTimebase
import kotlin.random.Random

/**
 * The station reads the five hot messages in place unless someone wants them as objects: both
 * ways must leave a vehicle's telemetry the same. Two stations hear the same random frames (random
 * fields, MAVLink 2 payloads truncated anywhere, some from another component); on one, a collector
 * of the vehicle's messages makes every frame go through io.dronefleet objects.
 */
class InPlaceTelemetryTest : StringSpec({
    val encoder = FrameEncoder()
    val hot = intArrayOf(0, 1, 30, 33, 74)
    val lengths = mapOf(0 to 9, 1 to 43, 30 to 28, 33 to 28, 74 to 20)

    fun randomFrame(random: Random, sequence: Int): ByteArray {
        val id = hot[random.nextInt(hot.size)]
        val full = random.nextBytes(lengths.getValue(id))
        // Plausible positions too, so that both paths store some instead of refusing them all.
        if (id == 33 && random.nextBoolean()) {
            writeInt(full, 4, random.nextInt(-900_000_000, 900_000_000))
            writeInt(full, 8, random.nextInt(-1_800_000_000, 1_800_000_000))
        }
        val payload = full.copyOf(1 + random.nextInt(full.size))
        val component = if (random.nextInt(8) == 0) 2 else 1
        return encoder.encode(MavFrame(2, sequence and 0xFF, 1, component, id, payload))
    }

    fun snapshot(v: MavlinkVehicle): List<Any?> = with(v.telemetry) {
        listOf(position.value, attitude.value, battery.value, hud.value, mode.value, armed.value, systemStatus.value, linkQuality.value, v.identity.value, v.payloads.value)
    }

    "telemetry read in place equals telemetry from decoded objects, frame by frame" {
        checkAll(25, Arb.long()) { seed ->
            runTest {
                val random = Random(seed)
                val inPlace = station()
                val objects = station()
                val peer = LinkPeer("vehicle")
                val first = copterHeartbeat(1, 0)
                inPlace.feed(peer, first)
                objects.feed(peer, first)
                val a = inPlace.vehicle(1)
                val b = objects.vehicle(1)
                var collected = 0
                backgroundScope.launch { b.messages.collect { collected++ } }
                testScheduler.runCurrent()
                a.wantsObjects shouldBe false
                b.wantsObjects shouldBe true
                val count = 1 + random.nextInt(80)
                for (i in 1..count) {
                    val frame = randomFrame(random, i)
                    inPlace.feed(peer, frame)
                    objects.feed(peer, frame)
                    snapshot(a) shouldBe snapshot(b)
                }
                testScheduler.runCurrent()
                collected shouldBe count // the collected vehicle still gets every frame as an object
            }
        }
    }
})

/** A station on a link that hands its per-datagram handler to the test, which then plays the receive thread. */
private class FedStation(val station: GroundStation, private val link: HandlerLink) {
    fun feed(peer: LinkPeer, bytes: ByteArray) = checkNotNull(link.handler) { "the station is not receiving" }(peer, bytes)

    fun vehicle(systemId: Int): MavlinkVehicle = checkNotNull(station.vehicles.value[systemId]) { "no vehicle $systemId" }
}

private fun TestScope.station(): FedStation {
    val link = HandlerLink()
    val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = virtualTimebase())
    val station = GroundStation.open(link, backgroundScope, config)
    testScheduler.runCurrent()
    return FedStation(station, link)
}

private class HandlerLink : MavlinkLink {
    override val address: LinkAddress = LinkAddress.UdpIn("127.0.0.1", 0)
    override val localPort: Int = 0
    override val peers: Collection<LinkPeer> = emptyList()
    var handler: ((LinkPeer, ByteArray) -> Unit)? = null

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        handler = onBytes
        awaitCancellation()
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) {}

    override fun close() {}
}

private fun writeInt(bytes: ByteArray, at: Int, value: Int) {
    for (i in 0 until 4) bytes[at + i] = (value ushr (8 * i)).toByte()
}
