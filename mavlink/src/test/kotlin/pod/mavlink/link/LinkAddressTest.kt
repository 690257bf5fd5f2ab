package pod.mavlink.link

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain

class LinkAddressTest : StringSpec({

    "MAVSDK and pymavlink forms parse to the same address" {
        listOf(
            Pair("udpin://0.0.0.0:14550", LinkAddress.UdpIn("0.0.0.0", 14550)),
            Pair("udpin:0.0.0.0:14550", LinkAddress.UdpIn("0.0.0.0", 14550)),
            Pair("udp://:14540", LinkAddress.UdpIn("0.0.0.0", 14540)),
            Pair("udpout://127.0.0.1:14550", LinkAddress.UdpOut("127.0.0.1", 14550)),
            Pair("udpout:127.0.0.1:14550", LinkAddress.UdpOut("127.0.0.1", 14550)),
            Pair("tcp://127.0.0.1:5760", LinkAddress.Tcp("127.0.0.1", 5760)),
            Pair("tcp:localhost:5760", LinkAddress.Tcp("localhost", 5760)),
            Pair("udpin://[::1]:14550", LinkAddress.UdpIn("::1", 14550)),
        ).forEach { (text, expected) -> LinkAddress.parse(text) shouldBe expected }
    }

    "a bad connection string names what was expected" {
        listOf(
            Pair("serial:/dev/ttyUSB0", "needs a baud rate after the device"),
            Pair("ttyUSB0", "expected udpin://"),
            Pair("udpin://0.0.0.0", "expected udpin://"),
            Pair("udpout://127.0.0.1:99999", "port must be 0..65535, was 99999"),
            Pair("udpout://127.0.0.1:0", "udpout needs a destination port"),
            Pair("tcp:127.0.0.1:0", "tcp needs a destination port"),
        ).forEach { (text, reason) ->
            val error = shouldThrow<InvalidConnectionString> { LinkAddress.parse(text) }
            error.message!! shouldContain reason
            error.text shouldBe text
        }
    }

    "an IPv6 address prints in brackets and reads back as the same address" {
        val address = LinkAddress.parse("udpin://[::1]:14551")
        address.toString() shouldBe "udpin://[::1]:14551"
        PortInUse(address).message!! shouldContain "cannot listen on [::1]:14551"
        LinkAddress.parse(address.toString()) shouldBe address
        LinkAddress.parse("tcp:[fe80::1]:5760").toString() shouldBe "tcp://[fe80::1]:5760"
        LinkAddress.parse("udpout:127.0.0.1:14550").toString() shouldBe "udpout://127.0.0.1:14550"
    }
})
