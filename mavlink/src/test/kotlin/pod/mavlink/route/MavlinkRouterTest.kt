package pod.mavlink.route

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.delay
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.runTest
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.virtualTimebase
import kotlin.time.Duration.Companion.seconds

/**
 * The routing rules one by one (see [RouteTable]), on a memory network in virtual time: a router
 * with a listening link for vehicles (14550), a listening link for ground stations (14551) and a
 * `udpout` link to a ground station listening on 14560.
 */
class MavlinkRouterTest : StringSpec({

    class Bench(scope: TestScope, config: (RouterConfig) -> RouterConfig = { it }) {
        val timebase = scope.virtualTimebase()
        val network = MemoryNetwork(scope.backgroundScope, timebase)
        val vehicles = network.open("udpin://127.0.0.1:14550")
        val stations = network.open("udpin://127.0.0.1:14551")
        val out = network.open("udpout://127.0.0.1:14560")
        val router = MavlinkRouter.start(listOf(vehicles, stations, out), scope.backgroundScope, config(RouterConfig(timebase = timebase)))
        val v1 = Node.toListening("v1", network, 14550, scope.backgroundScope)
        val v2 = Node.toListening("v2", network, 14550, scope.backgroundScope)
        val gcsA = Node.toListening("gcsA", network, 14551, scope.backgroundScope)
        val gcsB = Node.listening("gcsB", network, 14560, out, scope.backgroundScope)
        private val test = scope

        fun send(node: Node, bytes: ByteArray) {
            node.send(bytes)
            test.testScheduler.runCurrent()
        }

        /** Vehicles 1 and 2 (component 1) and both stations (255/190 and 254/190) have been heard. */
        fun allHeard() {
            send(v1, heartbeat(1, 1))
            send(v2, heartbeat(2, 1))
            send(gcsA, heartbeat(255, 190))
            send(gcsB, heartbeat(254, 190))
            listOf(v1, v2, gcsA, gcsB).forEach { it.received.clear() }
        }
    }

    "a frame with no target goes to every other endpoint once, never back to its sender" {
        runTest {
            val b = Bench(this)
            b.send(b.v1, heartbeat(1, 1, tag = 7))
            val hb = heartbeat(1, 1, tag = 7).hex()
            b.gcsB.receivedHex() shouldContainExactly listOf(hb) // a udpout remote is an endpoint from the start
            b.v1.receivedHex().shouldBeEmpty()
            b.v2.receivedHex().shouldBeEmpty() // not heard yet: the router does not know it
            b.gcsA.receivedHex().shouldBeEmpty()
            b.send(b.gcsA, heartbeat(255, 190))
            b.send(b.v1, heartbeat(1, 1, tag = 8))
            b.gcsA.receivedHex() shouldContainExactly listOf(heartbeat(1, 1, tag = 8).hex())
        }
    }

    "each peer of a listening link is an endpoint of its own: a command goes only to the peer its target system was heard from" {
        runTest {
            val b = Bench(this)
            b.allHeard()
            b.send(b.gcsA, command(255, 190, targetSys = 2, targetComp = 1, tag = 1))
            b.v2.receivedHex() shouldContainExactly listOf(command(255, 190, 2, 1, 1).hex())
            b.v1.receivedHex().shouldBeEmpty()
            b.gcsB.receivedHex().shouldBeEmpty()
        }
    }

    "target component 0 reaches any component of the system; a component above 0 only where that component was heard" {
        runTest {
            val b = Bench(this)
            b.allHeard()
            b.send(b.v1, heartbeat(1, 100)) // a camera of vehicle 1, on the same peer
            b.v2.received.clear()
            b.send(b.gcsA, command(255, 190, targetSys = 1, targetComp = 0, tag = 2))
            b.send(b.gcsA, command(255, 190, targetSys = 1, targetComp = 100, tag = 3))
            b.send(b.gcsA, command(255, 190, targetSys = 2, targetComp = 100, tag = 4)) // vehicle 2 has no component 100
            b.v1.receivedHex() shouldContainExactly listOf(command(255, 190, 1, 0, 2).hex(), command(255, 190, 1, 100, 3).hex())
            b.v2.receivedHex().shouldBeEmpty()
            b.router.stats()[1].unrouted shouldBe 1
        }
    }

    "target system 0 is a broadcast: every endpoint but the sender's" {
        runTest {
            val b = Bench(this)
            b.allHeard()
            b.send(b.gcsB, command(254, 190, targetSys = 0, targetComp = 0, tag = 5))
            val c = command(254, 190, 0, 0, 5).hex()
            listOf(b.v1, b.v2, b.gcsA).forEach { it.receivedHex() shouldContainExactly listOf(c) }
            b.gcsB.receivedHex().shouldBeEmpty()
        }
    }

    "a frame whose target was never heard goes nowhere and is counted unrouted on its link" {
        runTest {
            val b = Bench(this)
            b.allHeard()
            b.send(b.gcsA, command(255, 190, targetSys = 42, targetComp = 1))
            listOf(b.v1, b.v2, b.gcsB).forEach { it.receivedHex().shouldBeEmpty() }
            val stats = b.router.stats()
            stats[1].unrouted shouldBe 1
            stats[1].received shouldBe 2
        }
    }

    "a frame never goes where its sender was heard, even through another endpoint (no loops)" {
        runTest {
            val b = Bench(this)
            b.allHeard()
            // The same ground station id heard behind both station endpoints (two GCS apps as 255/190).
            b.send(b.gcsB, heartbeat(255, 190))
            listOf(b.v1, b.v2, b.gcsA).forEach { it.received.clear() }
            b.send(b.gcsA, heartbeat(255, 190, tag = 9))
            b.gcsB.receivedHex().shouldBeEmpty()
            b.v1.receivedHex() shouldContainExactly listOf(heartbeat(255, 190, tag = 9).hex())
            // A vehicle's reply to 255/190 reaches both.
            b.send(b.v1, command(1, 1, targetSys = 255, targetComp = 190, tag = 10))
            b.gcsA.receivedHex() shouldContainExactly listOf(command(1, 1, 255, 190, 10).hex())
            b.gcsB.receivedHex() shouldContainExactly listOf(command(1, 1, 255, 190, 10).hex())
        }
    }

    "a signed frame and a truncated MAVLink 2 payload go out byte for byte as they came in" {
        runTest {
            val b = Bench(this)
            b.allHeard()
            val plain = command(255, 190, targetSys = 1, targetComp = 0, tag = 0) // zeros at the end: truncated
            val decoded = mutableListOf<MavFrame>()
            pod.mavlink.codec.FrameDecoder().feed(plain) { decoded += it }
            val f = decoded.single()
            val signed = FrameEncoder().encode(
                MavFrame(2, 17, f.systemId, f.componentId, f.messageId, f.payload, signature = ByteArray(13) { (it * 19 + 3).toByte() }),
            )
            b.send(b.gcsA, plain)
            b.send(b.gcsA, signed)
            b.v1.receivedHex() shouldContainExactly listOf(plain.hex(), signed.hex())
            (f.payload.size < 33) shouldBe true
        }
    }

    "a listening link remembers at most maxPeersPerLink peers and forgets one silent for forgetPeersAfter" {
        runTest {
            val b = Bench(this) { it.copy(maxPeersPerLink = 2, forgetPeersAfter = 5.seconds) }
            b.allHeard()
            val v3 = Node.toListening("v3", b.network, 14550, backgroundScope)
            b.send(v3, heartbeat(3, 1)) // evicts v1, heard least recently
            b.router.stats()[0].evictedPeers shouldBe 1
            b.router.stats()[0].peers shouldBe 2
            b.send(b.gcsA, command(255, 190, targetSys = 1, targetComp = 1))
            b.v1.receivedHex().shouldBeEmpty()
            b.router.stats()[1].unrouted shouldBe 1
            delay(7.seconds) // everyone silent
            b.router.stats()[0].peers shouldBe 0
            b.router.stats()[0].evictedPeers shouldBe 1
            b.router.stats()[2].peers shouldBe 1 // the udpout remote stays
        }
    }

    "frames with a bad CRC are dropped and counted; the router routes on" {
        runTest {
            val b = Bench(this)
            b.allHeard()
            val bad = heartbeat(1, 1, tag = 11).also { it[it.size - 3] = (it[it.size - 3] + 1).toByte() }
            b.send(b.v1, bad)
            b.send(b.v1, heartbeat(1, 1, tag = 12))
            b.gcsA.receivedHex() shouldContainExactly listOf(heartbeat(1, 1, tag = 12).hex())
            b.router.stats()[0].badCrc shouldBe 1
        }
    }
})
