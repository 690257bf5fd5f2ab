package pod.sim.radio

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.longs.shouldBeInRange
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import pod.mavlink.link.LinkPeer

class SerialBufferTest : StringSpec({

    "a 57600-baud line carries 5760 bytes a second and drops what overflows its 2048-byte buffer" {
        runTest {
            val buffer = SerialBuffer(2048, SikRadio(baud = 57_600).bytesPerSecond, testScheduler.timeSource)
            val arrived = ArrayList<Pair<Long, Int>>()
            val drain = launch { buffer.drain { _, bytes -> arrived += testScheduler.currentTime to bytes.size } }
            val peer = LinkPeer("ground")
            repeat(30) { buffer.offer(peer, ByteArray(100)) } // 3000 bytes at once
            buffer.dropped shouldBe 952
            buffer.freePercent() shouldBe 0
            testScheduler.advanceTimeBy(1_000)
            testScheduler.runCurrent()
            buffer.carried shouldBe 2048
            arrived.sumOf { it.second } shouldBe 2048
            arrived.last().first shouldBeInRange 355L..356L // 2048 bytes ÷ 5760 bytes/s
            arrived.first().first shouldBeInRange 17L..18L // one 100-byte chunk: 17.4 ms
            buffer.freePercent() shouldBe 100
            drain.cancel()
        }
    }

    "free space is reported in SiK's 8-byte steps" {
        runTest {
            val buffer = SerialBuffer(2048, 5760.0, testScheduler.timeSource)
            buffer.offer(LinkPeer("ground"), ByteArray(1024))
            buffer.freePercent() shouldBe 50
            buffer.offer(LinkPeer("ground"), ByteArray(7))
            buffer.freePercent() shouldBe 49 // 1017 free: 127 of 256 steps
        }
    }
})
