package pod.mavlink.link

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.async
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import java.io.IOException
import java.util.concurrent.CopyOnWriteArrayList
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

private fun link(first: ByteStream, reopening: Reopening?) =
    StreamLink(LinkAddress.Serial("/dev/test", 57600), "test link", "was closed by the remote", first, "peer", 0, reopening)

/** A stream whose reads come from [reads] and whose writes are kept in [written] (or fail). */
private class ScriptedStream(private val failWrites: Boolean = false) : ByteStream {
    val reads = Channel<ByteArray>(Channel.UNLIMITED)
    val written = CopyOnWriteArrayList<Byte>()

    fun end() = reads.close()

    override suspend fun read(buffer: ByteArray): Int {
        val chunk = reads.receiveCatching().getOrNull() ?: return -1
        chunk.copyInto(buffer)
        return chunk.size
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
