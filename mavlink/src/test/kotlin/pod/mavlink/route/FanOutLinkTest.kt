package pod.mavlink.route

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.virtualTimebase

/** [FanOutLink]: one sender, several ground stations. */
class FanOutLinkTest : StringSpec({

    "what is sent to all reaches every link; a reply goes back only on the link its peer was heard on; split frames arrive whole" {
        runTest {
            val network = MemoryNetwork(backgroundScope, virtualTimebase())
            val first = network.open("udpout://127.0.0.1:14550")
            val second = network.open("udpout://127.0.0.1:14551")
            val fan = FanOutLink(listOf(first, second))
            val a = Node.listening("a", network, 14550, first, backgroundScope)
            val b = Node.listening("b", network, 14551, second, backgroundScope)
            val heard = ArrayList<Pair<LinkPeer, ByteArray>>()
            backgroundScope.launch { fan.receive { peer, bytes -> heard += peer to bytes } }
            fan.sendToAll(heartbeat(1, 1, 1))
            testScheduler.runCurrent()
            a.receivedHex() shouldContainExactly listOf(heartbeat(1, 1, 1).hex())
            b.receivedHex() shouldContainExactly listOf(heartbeat(1, 1, 1).hex())
            fan.peers.size shouldBe 2
            val cmd = command(255, 190, 1, 1, 5)
            b.send(cmd.copyOfRange(0, 10))
            testScheduler.runCurrent()
            heard.shouldBeEmpty()
            b.send(cmd.copyOfRange(10, cmd.size))
            testScheduler.runCurrent()
            heard.map { it.second.hex() } shouldContainExactly listOf(cmd.hex())
            a.received.clear()
            b.received.clear()
            fan.sendNow(heartbeat(1, 1, 2), heard.single().first)
            testScheduler.runCurrent()
            a.receivedHex().shouldBeEmpty()
            b.receivedHex() shouldContainExactly listOf(heartbeat(1, 1, 2).hex())
        }
    }
})
