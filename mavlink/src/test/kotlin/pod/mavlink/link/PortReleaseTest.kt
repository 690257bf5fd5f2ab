package pod.mavlink.link

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import java.net.DatagramSocket
import java.net.InetAddress
import kotlin.time.Duration.Companion.seconds

/**
 * One `pod` command after another on the same `udpin` port: each binds the port the previous one
 * just closed. A socket registered with a selector is released only when the selector next
 * deregisters it, after close() returns (Ktor's UDP link did that; TCP links still do), so a
 * station must be able to wait for its release ([GroundStation.closeAndAwait]) or the next bind can
 * find the port in use.
 */
class PortReleaseTest : StringSpec({

    "a station closed with closeAndAwait has released its port: the next station binds it at once, every time" {
        val port = DatagramSocket(0, InetAddress.getByName("127.0.0.1")).use { it.localPort }
        coroutineScope {
            repeat(40) {
                val station = GroundStation.open("udpin:127.0.0.1:$port", this)
                station.link.localPort shouldBe port
                withTimeout(5.seconds) { station.closeAndAwait() }
                // The port is free for anyone now, not only for another Ktor socket.
                DatagramSocket(port, InetAddress.getByName("127.0.0.1")).use { it.localPort shouldBe port }
            }
        }
    }
})
