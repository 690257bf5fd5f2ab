package pod.mavlink.link

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import java.net.InetSocketAddress
import java.nio.ByteBuffer
import java.nio.channels.DatagramChannel
import java.util.Collections
import kotlin.time.Duration.Companion.seconds

/**
 * Many UDP links in one process (a simulated fleet, `pod route`) share a few receive threads, one
 * selector each: every datagram still reaches its own link's handler, and one link's failure or
 * closing leaves the others receiving. Real loopback sockets; about a second.
 */
class SharedReceiveTest : StringSpec({
    fun receiveThreads() = Thread.getAllStackTraces().keys.filter { it.name.startsWith("pod-udp-receive") && it.isAlive }
    fun send(to: Int, vararg payload: Byte) = DatagramChannel.open().use { it.send(ByteBuffer.wrap(payload), InetSocketAddress("127.0.0.1", to)) }
    val cores = Runtime.getRuntime().availableProcessors()

    "60 links receive on at most one thread per core, each datagram reaching its own link's handler in order" {
        val links = List(60) { MavlinkLink.open("udpin://127.0.0.1:0") }
        val seen = List(links.size) { Collections.synchronizedList(ArrayList<Int>()) }
        val threads = Collections.synchronizedSet(HashSet<String>())
        coroutineScope {
            val receiving = links.mapIndexed { i, link ->
                launch { link.receive { _, bytes -> threads += Thread.currentThread().name; seen[i] += bytes[0] * 256 + bytes[1] } }
            }
            DatagramChannel.open().use { sender ->
                for (round in 0 until 5) for ((i, link) in links.withIndex()) {
                    sender.send(ByteBuffer.wrap(byteArrayOf(i.toByte(), round.toByte())), InetSocketAddress("127.0.0.1", link.localPort))
                }
            }
            withTimeout(5.seconds) { while (seen.any { it.size < 5 }) delay(5) }
            receiveThreads().size shouldBeLessThanOrEqual cores
            links.forEach { it.close() }
            withTimeout(5.seconds) { receiving.forEach { it.join() } }
        }
        threads.size shouldBeLessThanOrEqual cores
        seen.forEachIndexed { i, got -> got shouldBe (0 until 5).map { i * 256 + it } }
        withTimeout(5.seconds) { while (receiveThreads().isNotEmpty()) delay(10) }
        receiveThreads().shouldBeEmpty()
    }

    "a handler that throws ends its own link's receive with that error; every link beside it keeps receiving" {
        // More links than threads: the failing one shares its thread with another.
        val links = List(cores + 2) { MavlinkLink.open("udpin://127.0.0.1:0") }
        val heard = List(links.size) { Collections.synchronizedList(ArrayList<Byte>()) }
        coroutineScope {
            val failing = async {
                runCatching { links[0].receive { _, bytes -> if (bytes[0] == 66.toByte()) error("handler broke on 66") } }
            }
            val others = links.drop(1).mapIndexed { i, link -> launch { link.receive { _, bytes -> heard[i + 1] += bytes[0] } } }
            send(links[0].localPort, 66)
            val error = withTimeout(5.seconds) { failing.await() }.exceptionOrNull()
            error?.message shouldBe "handler broke on 66"
            for (link in links.drop(1)) send(link.localPort, 7)
            withTimeout(5.seconds) { while (heard.drop(1).any { it.isEmpty() }) delay(5) }
            heard.drop(1).forEach { it shouldBe listOf(7.toByte()) }
            // The failed link stays open for sends until it is closed, as before the failure.
            links[0].close()
            withTimeout(5.seconds) { links[0].awaitClosed() }
            // A closed link receives nothing: receive returns at once.
            withTimeout(5.seconds) { links[0].receive { _, _ -> error("a closed link delivered") } }
            links.drop(1).forEach { it.close() }
            withTimeout(5.seconds) { others.forEach { it.join() } }
        }
    }
})
