package pod.mavlink.link

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.async
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.TestFrames
import pod.mavlink.codec.decodeAll
import pod.mavlink.codec.toHex
import java.io.IOException
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * [StreamLink]'s two ways of going down, on scripted streams in virtual time: final (TCP) and
 * reopening (serial). The real streams are exercised by TcpLinkTest and the e2e SerialLinkSpec.
 */
@OptIn(ExperimentalCoroutinesApi::class)
class StreamLinkTest : StringSpec({

    "without reopening, a stream that ends is final: receive throws and later sends throw the same reason" {
        runTest {
            val stream = ScriptedStream()
            val link = link(stream, reopening = null)
            val receiving = async { runCatching { link.receive { _, _ -> } }.exceptionOrNull() }
            stream.end()
            receiving.await()!!.message shouldBe "test link was closed by the remote"
            link.state.value shouldBe LinkState.Down("test link was closed by the remote", reopens = false)
            shouldThrow<LinkException> { link.sendToAll(byteArrayOf(1)) }.message shouldBe "test link was closed by the remote"
        }
    }

    "with reopening, a failed write drops that send, the receive loop opens a new stream after failed attempts, and sends go to it" {
        runTest {
            val first = ScriptedStream(failWrites = true)
            val second = ScriptedStream()
            val attempts = Channel<ScriptedStream?>(Channel.UNLIMITED).apply { trySend(null); trySend(null); trySend(second) }
            val link = link(first, Reopening(open = { attempts.receive() ?: throw LinkException("still missing") }, first = 250.milliseconds, longest = 1.seconds))
            val got = MutableStateFlow<List<Byte>>(emptyList())
            val receiving = launch { link.receive { _, bytes -> got.value += bytes.asList() } }

            link.sendToAll(byteArrayOf(1, 2, 3)) // the write fails: dropped, not thrown
            link.counters.droppedSends shouldBe 1
            link.state.value.toString() shouldContain "test link broke: unplugged"
            link.sendToAll(byteArrayOf(4)) // down: dropped at once
            link.counters.droppedBytes shouldBe 4

            link.state.first { it == LinkState.Up }
            link.counters shouldBe StreamCounters(outages = 1, reopens = 1, failedReopens = 2, droppedSends = 2, droppedBytes = 4)
            link.sendToAll(byteArrayOf(5, 6))
            second.written shouldBe listOf<Byte>(5, 6)
            second.reads.send(byteArrayOf(7))
            got.first { it.isNotEmpty() } shouldBe listOf<Byte>(7)
            link.close()
            receiving.join()
            link.state.value shouldBe LinkState.Closed
        }
    }

    "frames carried by a stream link and cut anywhere decode to the frames one datagram each would give" {
        checkAll(60, Arb.long()) { seed ->
            val random = Random(seed)
            val frames = List(1 + random.nextInt(24)) { TestFrames.random(random) }
            val asDatagrams = frames.flatMap { FrameDecoder().decodeAll(it) }.map(::describe)
            val stream = ScriptedStream()
            TestFrames.split(frames.reduce { a, b -> a + b }, random).forEach { stream.reads.trySend(it) }
            stream.end()
            val decoder = FrameDecoder()
            val got = mutableListOf<String>()
            runTest {
                val link = link(stream, reopening = null)
                shouldThrow<LinkException> { link.receive { _, bytes -> decoder.feed(bytes) { got += describe(it) } } }
            }
            got shouldBe asDatagrams
        }
    }

    "close() during the retries ends receive at once and the device is not tried again" {
        runTest {
            val stream = ScriptedStream()
            var tries = 0
            val link = link(stream, Reopening(open = { tries++; throw LinkException("still missing") }))
            val receiving = launch(start = CoroutineStart.UNDISPATCHED) { link.receive { _, _ -> } }
            stream.end()
            link.state.first { it is LinkState.Down && it.failedReopens >= 3 }
            link.close()
            receiving.join()
            val after = tries
            testScheduler.advanceTimeBy(10.seconds)
            tries shouldBe after
        }
    }
})

private fun describe(frame: MavFrame): String =
    "v${frame.version} seq ${frame.sequence} ${frame.systemId}/${frame.componentId} id ${frame.messageId} ${frame.payload.toHex()} ${frame.signature?.toHex()}"

private fun link(first: ByteStream, reopening: Reopening?) =
    StreamLink(LinkAddress.Serial("/dev/test", 57600), "test link", "was closed by the remote", first, "peer", 0, reopening)

/** A stream whose reads come from [reads] and whose writes are kept in [written] (or fail). */
private class ScriptedStream(private val failWrites: Boolean = false) : ByteStream {
    val reads = Channel<ByteArray>(Channel.UNLIMITED)
    val written = CopyOnWriteArrayList<Byte>()

    fun end() = reads.close()

    private var pending = ByteArray(0)

    // Hands out each chunk as it came, in pieces when it is larger than the reader's buffer.
    override suspend fun read(buffer: ByteArray): Int {
        if (pending.isEmpty()) pending = reads.receiveCatching().getOrNull() ?: return -1
        val n = minOf(pending.size, buffer.size)
        pending.copyInto(buffer, 0, 0, n)
        pending = pending.copyOfRange(n, pending.size)
        return n
    }

    override suspend fun write(bytes: ByteArray): Int {
        if (failWrites) throw IOException("unplugged")
        written += bytes.asList()
        return bytes.size
    }

    override fun close() {
        reads.close()
    }
}
