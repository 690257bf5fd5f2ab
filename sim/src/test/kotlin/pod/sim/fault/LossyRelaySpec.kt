package pod.sim.fault

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withTimeout
import java.net.InetAddress
import java.net.InetSocketAddress
import java.nio.ByteBuffer
import java.nio.channels.ClosedChannelException
import java.nio.channels.DatagramChannel
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

class LossyRelaySpec : StringSpec({

    "without faults it forwards both ways byte for byte and in order between a listening GCS and two sending vehicles" {
        val gcs = UdpPeer()
        val vehicles = listOf(UdpPeer(), UdpPeer())
        val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:${gcs.port}", seed = 1)
        withRelay(relay, gcs, *vehicles.toTypedArray()) {
            val up = payloads(300, seed = 1)
            up.forEachIndexed { i, bytes -> lockstep(relay, AtoB, vehicles[i % 2], relay.portA, listOf(gcs), bytes) }
            val atGcs = gcs.take(300)
            atGcs.map { it.bytes.toList() } shouldBe up.map { it.toList() }
            atGcs.map { it.from.port }.toSet() shouldBe setOf(relay.portB)

            // The GCS answers where the traffic came from; both vehicles were heard, so both get it.
            val down = payloads(100, seed = 2)
            down.forEach { lockstep(relay, BtoA, gcs, atGcs.first().from.port, vehicles, it) }
            for (vehicle in vehicles) vehicle.take(100).map { it.bytes.toList() } shouldBe down.map { it.toList() }
            relay.counters.value shouldBe RelayCounters(LinkCounters(sent = 300, delivered = 300), LinkCounters(sent = 100, delivered = 100))
        }
    }

    "a GCS that sends first reaches a listening vehicle, and the vehicle's replies come back unchanged" {
        val vehicle = UdpPeer()
        val gcs = UdpPeer()
        val relay = LossyRelay("udpin:127.0.0.1:0", "udpout:127.0.0.1:${vehicle.port}", seed = 2)
        withRelay(relay, gcs, vehicle) {
            val requests = payloads(50, seed = 3)
            requests.forEach { lockstep(relay, AtoB, gcs, relay.portA, listOf(vehicle), it) }
            val atVehicle = vehicle.take(50)
            atVehicle.map { it.bytes.toList() } shouldBe requests.map { it.toList() }

            val replies = payloads(50, seed = 4)
            replies.forEach { lockstep(relay, BtoA, vehicle, atVehicle.first().from.port, listOf(gcs), it) }
            gcs.take(50).map { it.bytes.toList() } shouldBe replies.map { it.toList() }
        }
    }

    "with both sides listening it learns each side from its first datagram and discards what has nowhere to go yet" {
        val vehicle = UdpPeer()
        val gcs = UdpPeer()
        val relay = LossyRelay("udpin://127.0.0.1:0", "udpin://127.0.0.1:0")
        withRelay(relay, gcs, vehicle) {
            gcs.sendTo(relay.portB, byteArrayOf(1))
            relay.counters.first { it.bToA.discarded == 1L }
            lockstep(relay, AtoB, vehicle, relay.portA, listOf(gcs), byteArrayOf(2))
            lockstep(relay, BtoA, gcs, relay.portB, listOf(vehicle), byteArrayOf(3))
            gcs.take(1).single().bytes.toList() shouldBe listOf<Byte>(2)
            vehicle.take(1).single().bytes.toList() shouldBe listOf<Byte>(3)
            relay.counters.value.bToA shouldBe LinkCounters(sent = 2, delivered = 1, discarded = 1)
        }
    }

    "drop 0.3 loses about 30% of a paced burst, exactly the datagrams the counters report, and keeps the rest in order" {
        val vehicle = UdpPeer()
        val gcs = UdpPeer()
        val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:${gcs.port}", aToB = LinkFaults(drop = 0.3), seed = 7)
        withRelay(relay, gcs, vehicle) {
            val burst = List(2000) { i -> ByteBuffer.allocate(4).putInt(i).array() }
            burst.forEach { lockstep(relay, AtoB, vehicle, relay.portA, listOf(gcs), it) }
            val counters = relay.counters.value.aToB
            counters.sent shouldBe 2000
            counters.delivered shouldBe 2000 - counters.dropped
            (counters.dropped / 2000.0) shouldBe (0.3 plusOrMinus 0.05)
            val arrived = gcs.take(counters.delivered.toInt()).map { ByteBuffer.wrap(it.bytes).int }
            arrived shouldBe arrived.sorted()
            arrived.toSet().size shouldBe arrived.size
        }
    }

    "the same seed loses the same datagrams on every run" {
        suspend fun survivors(seed: Long): List<Int> {
            val vehicle = UdpPeer()
            val gcs = UdpPeer()
            val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:${gcs.port}", aToB = LinkFaults(drop = 0.3), seed = seed)
            var arrived = emptyList<Int>()
            withRelay(relay, gcs, vehicle) {
                List(300) { i -> ByteBuffer.allocate(4).putInt(i).array() }
                    .forEach { lockstep(relay, AtoB, vehicle, relay.portA, listOf(gcs), it) }
                arrived = gcs.take(relay.counters.value.aToB.delivered.toInt()).map { ByteBuffer.wrap(it.bytes).int }
            }
            return arrived
        }
        val first = survivors(seed = 21)
        survivors(seed = 21) shouldBe first
        survivors(seed = 22) shouldNotBe first
    }

    "delay, jitter, duplication and corruption together: every copy the counters call delivered arrives, altered as counted" {
        val vehicle = UdpPeer()
        val gcs = UdpPeer()
        val faults = LinkFaults(drop = 0.1, duplicate = 0.2, corrupt = 0.2, delay = 5.milliseconds, jitter = 10.milliseconds)
        val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:${gcs.port}", aToB = faults, seed = 3)
        withRelay(relay, gcs, vehicle) {
            val sent = payloads(300, seed = 5)
            sent.forEach { lockstep(relay, AtoB, vehicle, relay.portA, listOf(gcs), it) }
            val settled = relay.counters.first { it.aToB.delivered == it.aToB.sent - it.aToB.dropped + it.aToB.duplicated }.aToB
            settled.discarded shouldBe 0
            val arrived = gcs.take(settled.delivered.toInt()).map { it.bytes }
            // Each arrival is a sent datagram with at most one byte changed.
            arrived.all { got -> sent.any { it.size == got.size && it.indices.count { i -> it[i] != got[i] } <= 1 } } shouldBe true
            // A corrupted datagram that was also duplicated arrives twice, identically: count distinct ones.
            arrived.filter { got -> sent.none { it.contentEquals(got) } }.map { it.toList() }.toSet().size.toLong() shouldBe
                settled.corrupted
        }
    }

    "reorder over the wire delivers every datagram, some out of order, the last held ones when maxHold runs out" {
        val vehicle = UdpPeer()
        val gcs = UdpPeer()
        val faults = LinkFaults(reorder = 0.3, maxHold = 50.milliseconds)
        val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:${gcs.port}", aToB = faults, seed = 11)
        withRelay(relay, gcs, vehicle) {
            val burst = List(200) { i -> ByteBuffer.allocate(4).putInt(i).array() }
            burst.forEach { lockstep(relay, AtoB, vehicle, relay.portA, listOf(gcs), it) }
            relay.counters.first { it.aToB.delivered == 200L }
            val arrived = gcs.take(200).map { ByteBuffer.wrap(it.bytes).int }
            arrived.sorted() shouldBe (0 until 200).toList()
            arrived shouldNotBe arrived.sorted()
            relay.counters.value.aToB.reordered shouldNotBe 0L
        }
    }

    "only loopback UDP is accepted, and ports exist only once started" {
        shouldThrow<IllegalArgumentException> { LossyRelay("udpin://0.0.0.0:0", "udpout://127.0.0.1:14550") }.message shouldBe
            "a must be on loopback (127.0.0.1, ::1 or localhost), was 0.0.0.0"
        shouldThrow<IllegalArgumentException> { LossyRelay("udpin://127.0.0.1:0", "tcp://127.0.0.1:5760") }.message shouldBe
            "b must be a udpin:// or udpout:// address, was tcp://127.0.0.1:5760"
        shouldThrow<IllegalArgumentException> { LossyRelay("udpin://127.0.0.1:0", "udpin://127.0.0.1:0", queueCapacity = 0) }
            .message shouldBe "queueCapacity must be ≥ 1, was 0"
        val relay = LossyRelay("udpin://127.0.0.1:0", "udpin://127.0.0.1:0")
        shouldThrow<IllegalStateException> { relay.portA }.message shouldContain "not started"
        // The relay's coroutines are children of this scope: it returns only if close() ended them.
        withTimeout(10.seconds) {
            coroutineScope {
                relay.start(this)
                relay.portA shouldNotBe relay.portB
                shouldThrow<IllegalStateException> { relay.start(this) }
                relay.close()
            }
        }
    }
})

private val AtoB: (RelayCounters) -> LinkCounters = { it.aToB }
private val BtoA: (RelayCounters) -> LinkCounters = { it.bToA }

private fun payloads(count: Int, seed: Int): List<ByteArray> {
    val random = Random(seed)
    return List(count) { random.nextBytes(1 + random.nextInt(280)) }
}

/**
 * Sends [bytes] and waits until the relay has taken it in and every peer in [to] holds all that
 * the relay forwarded in that [direction]: lockstep, so no socket buffer can overflow and any loss
 * is the relay's doing.
 */
private suspend fun lockstep(
    relay: LossyRelay,
    direction: (RelayCounters) -> LinkCounters,
    from: UdpPeer,
    port: Int,
    to: List<UdpPeer>,
    bytes: ByteArray,
) = withTimeout(10.seconds) {
    val before = direction(relay.counters.value).sent
    from.sendTo(port, bytes)
    val delivered = direction(relay.counters.first { direction(it).sent > before }).delivered
    for (peer in to) peer.received.first { it >= delivered }
}

/** Starts [relay] and [peers]' receivers, runs [body], then stops everything; the scope's return proves nothing was left running. */
private suspend fun withRelay(relay: LossyRelay, vararg peers: UdpPeer, body: suspend CoroutineScope.() -> Unit) {
    try {
        withTimeout(60.seconds) {
            coroutineScope {
                relay.start(this)
                val receivers = peers.map { it.listen(this) }
                try {
                    body()
                } finally {
                    receivers.forEach { it.cancelAndJoin() }
                    relay.close()
                }
            }
        }
    } finally {
        peers.forEach { it.close() }
    }
}

/** A plain NIO UDP socket on loopback, independent of Pod's links, that queues what it receives. */
private class UdpPeer : AutoCloseable {
    class Datagram(val bytes: ByteArray, val from: InetSocketAddress)

    private val loopback = InetAddress.getLoopbackAddress()
    private val channel = DatagramChannel.open().bind(InetSocketAddress(loopback, 0))
    private val inbox = Channel<Datagram>(Channel.UNLIMITED)

    val port: Int = (channel.localAddress as InetSocketAddress).port

    /** How many datagrams arrived so far. */
    val received = MutableStateFlow(0L)

    fun listen(scope: CoroutineScope): Job = scope.launch(Dispatchers.IO) {
        val buffer = ByteBuffer.allocate(65_536)
        try {
            while (true) {
                buffer.clear()
                val from = runInterruptible { channel.receive(buffer) } as InetSocketAddress
                buffer.flip()
                inbox.send(Datagram(ByteArray(buffer.remaining()).also { buffer.get(it) }, from))
                received.update { it + 1 }
            }
        } catch (_: ClosedChannelException) {
            // Cancelling interrupts the blocking receive, which closes the channel: the test is over.
        }
    }

    fun sendTo(port: Int, bytes: ByteArray) {
        channel.send(ByteBuffer.wrap(bytes), InetSocketAddress(loopback, port))
    }

    suspend fun take(count: Int): List<Datagram> = withTimeout(10.seconds) { List(count) { inbox.receive() } }

    override fun close() = channel.close()
}
