package pod.mavlink.link

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll

class SerialAddressTest : StringSpec({

    "MAVSDK and pymavlink serial forms parse to the same device and baud" {
        listOf(
            Pair("serial:///dev/ttyUSB0:57600", LinkAddress.Serial("/dev/ttyUSB0", 57600)),
            Pair("serial:/dev/ttyUSB0:57600", LinkAddress.Serial("/dev/ttyUSB0", 57600)),
            Pair("/dev/ttyUSB0,57600", LinkAddress.Serial("/dev/ttyUSB0", 57600)),
            Pair("  /dev/ttyACM0,921600 ", LinkAddress.Serial("/dev/ttyACM0", 921600)),
            Pair("serial://COM3:115200", LinkAddress.Serial("COM3", 115200)),
            Pair("com12,57600", LinkAddress.Serial("com12", 57600)),
            // by-path names hold colons of their own: the baud is after the last one.
            Pair(
                "serial:///dev/serial/by-path/pci-0000:00:14.0-usb-0:2:1.0-port0:57600",
                LinkAddress.Serial("/dev/serial/by-path/pci-0000:00:14.0-usb-0:2:1.0-port0", 57600),
            ),
        ).forEach { (text, expected) -> LinkAddress.parse(text) shouldBe expected }
    }

    "a bare device takes pymavlink's default of 115200 baud" {
        LinkAddress.parse("/dev/ttyUSB0") shouldBe LinkAddress.Serial("/dev/ttyUSB0", 115_200)
        LinkAddress.parse("COM4") shouldBe LinkAddress.Serial("COM4", 115_200)
    }

    "a serial address prints in the MAVSDK form and reads back as itself" {
        checkAll(Arb.element("/dev/ttyUSB0", "/dev/serial/by-id/usb-3D_Radio-if00-port0", "COM7", "/tmp/pty a"), Arb.int(1..20_000_000)) { path, baud ->
            val address = LinkAddress.Serial(path, baud)
            LinkAddress.parse(address.toString()) shouldBe address
            LinkAddress.parse("$path,$baud") shouldBe address
        }
    }

    "a malformed serial string is a typed error naming what is wrong" {
        listOf(
            Pair("serial:///dev/ttyUSB0", "needs a baud rate after the device"),
            Pair("serial:///dev/ttyUSB0:", "the baud rate must be digits, was ''"),
            Pair("/dev/ttyUSB0,", "the baud rate must be digits, was ''"),
            Pair("serial:///dev/ttyUSB0:fast", "the baud rate must be digits, was 'fast'"),
            Pair("/dev/ttyUSB0,0", "the baud rate must be 1..20000000, was 0"),
            Pair("serial:///dev/ttyUSB0:0000", "the baud rate must be 1..20000000, was 0000"),
            Pair("/dev/ttyUSB0,99999999999999999999", "the baud rate must be 1..20000000"),
            Pair("serial://:57600", "the serial device path is empty"),
            Pair(",57600", "the serial device path is empty"),
            Pair("serial://ttyUSB0:57600", "a serial device is a path starting with /"),
            Pair("serial://COMX:57600", "a serial device is a path starting with /"),
            Pair("/dev/ttyUSB0:57600", "a serial baud rate follows a comma (/dev/ttyUSB0,57600) or serial://"),
            Pair("serial_flowcontrol:///dev/ttyUSB0:57600", "hardware flow control is not supported"),
        ).forEach { (text, reason) ->
            val error = shouldThrow<InvalidConnectionString> { LinkAddress.parse(text) }
            error.message!! shouldContain reason
            error.text shouldBe text
        }
    }

    "a serial address has no host or port" {
        val address = LinkAddress.parse("/dev/ttyUSB0,57600")
        address.host shouldBe ""
        address.port shouldBe 0
    }
})
