package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeGreaterThanOrEqualTo
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.link.ByteStreamLink
import pod.mavlink.link.DeviceNotFound
import pod.mavlink.link.DeviceUnavailable
import pod.mavlink.link.LinkState
import pod.mavlink.link.MavlinkLink
import java.io.File
import kotlin.random.Random
import kotlin.time.Duration.Companion.seconds

/** [pod.mavlink.link.SerialLink] on a socat pseudo-terminal pair: bytes, a missing device, unplug and replug. */
class SerialLinkSpec : StringSpec({

    "bytes written at one end of a 57600-baud pair arrive in order at the other, both ways, and are counted" {
        linkedPair { _, a, b ->
            val there = Random(27).nextBytes(3000)
            there.asList().chunked(200).forEach { a.link.sendToAll(it.toByteArray()) }
            withTimeout(10.seconds) { b.received.first { it.size >= there.size } }.toByteArray() shouldBe there
            val back = Random(28).nextBytes(500)
            b.link.sendToAll(back)
            withTimeout(10.seconds) { a.received.first { it.size >= back.size } }.toByteArray() shouldBe back
            a.link.counters.bytesSent shouldBe 3000
            b.link.counters.bytesReceived shouldBe 3000
            a.link.counters.droppedSends shouldBe 0
            a.link.state.value shouldBe LinkState.Up
        }
    }

    "a missing device is DeviceNotFound at open, from the link and from a ground station alike" {
        val missing = "/nonexistent/pod-serial-${Random.nextInt(1_000_000)}"
        shouldThrow<DeviceNotFound> { MavlinkLink.open("serial://$missing:57600") }.message shouldBe "no serial device at $missing"
        coroutineScope {
            shouldThrow<DeviceNotFound> { GroundStation.open("$missing,57600", this) }.address.baud shouldBe 57600
        }
    }

    "a file that is no terminal is DeviceUnavailable at open, saying why" {
        val file = File.createTempFile("pod-not-a-tty", ".bin")
        try {
            val error = shouldThrow<DeviceUnavailable> { MavlinkLink.open("${file.path},57600") }
            error.message!! shouldContain "cannot open serial device ${file.path}"
        } finally {
            file.delete()
        }
    }

    "an unplugged device: the link goes down, drops and counts sends without blocking or throwing, and reopens the same path when it is back" {
        linkedPair { pair, a, b ->
            runInterruptible(Dispatchers.IO) { pair.unplug() }
            withTimeout(5.seconds) { a.link.state.first { it is LinkState.Down } }.shouldBeInstanceOf<LinkState.Down>().let {
                it.reopens shouldBe true
                it.reason shouldContain "serial link on ${pair.a}"
            }
            // Three sends while it is down: each returns at once, none goes anywhere.
            withTimeout(2.seconds) { repeat(3) { a.link.sendToAll(byteArrayOf(1, 2, 3, 4)) } }
            a.link.counters.droppedSends shouldBeGreaterThanOrEqualTo 3
            a.link.counters.droppedBytes shouldBeGreaterThanOrEqualTo 12

            runInterruptible(Dispatchers.IO) { pair.plugIn() }
            withTimeout(10.seconds) { a.link.state.first { it == LinkState.Up } }
            withTimeout(10.seconds) { b.link.state.first { it == LinkState.Up } }
            a.link.counters.outages shouldBe 1
            a.link.counters.reopens shouldBe 1

            // The same receive calls carry on with the new device behind the path.
            b.link.sendToAll("after".toByteArray())
            withTimeout(10.seconds) { a.received.first { String(it.toByteArray()).endsWith("after") } }
            a.link.sendToAll("back".toByteArray())
            withTimeout(10.seconds) { b.received.first { String(it.toByteArray()).endsWith("back") } }
        }
    }

    "close() while the device is missing ends the retries and the receive at once" {
        Socat.pair().use { pair ->
            coroutineScope {
                val a = openSerial(pair.a)
                val receiving = launch { a.receive { _, _ -> } }
                runInterruptible(Dispatchers.IO) { pair.unplug() }
                // Retrying (at most 1 s apart) against a path that stays missing.
                withTimeout(5.seconds) { a.state.first { it is LinkState.Down && it.failedReopens >= 2 } }
                a.close()
                withTimeout(2.seconds) { receiving.join() }
                withTimeout(2.seconds) { a.awaitClosed() }
                a.state.value shouldBe LinkState.Closed
            }
        }
    }
})

private suspend fun openSerial(path: String): ByteStreamLink =
    MavlinkLink.open("serial://$path:57600").shouldBeInstanceOf<ByteStreamLink>()

/** One end of a pair: its link, and everything it has received so far, in order. */
private class End(val link: ByteStreamLink, val received: MutableStateFlow<List<Byte>>)

/** A socat pair with a 57600-baud link open and receiving on each end; closes both after [block]. */
private suspend fun linkedPair(block: suspend CoroutineScope.(Socat, End, End) -> Unit) = Socat.pair().use { pair ->
    coroutineScope {
        val ends = listOf(pair.a, pair.b).map { path ->
            val link = openSerial(path)
            val bytes = MutableStateFlow<List<Byte>>(emptyList())
            launch { link.receive { _, chunk -> bytes.value += chunk.asList() } }
            End(link, bytes)
        }
        try {
            block(pair, ends[0], ends[1])
        } finally {
            ends.forEach { it.link.close() }
        }
    }
}
