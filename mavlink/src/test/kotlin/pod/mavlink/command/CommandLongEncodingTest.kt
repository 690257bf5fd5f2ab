package pod.mavlink.command

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.float
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll
import pod.mavlink.codec.FrameEncoder

/** [CommandWire.encodeLong], written by hand, frames byte for byte as [CommandWire.encode]'s io.dronefleet COMMAND_LONG. */
class CommandLongEncodingTest : StringSpec({
    val encoder = FrameEncoder()

    // Zeros often, so that MAVLink 2's trimming of trailing zero bytes is exercised too.
    val param = Arb.element(0f, 0f, 1f, -1f, Float.MAX_VALUE, Float.NaN, 1e-7f)
    val p = Arb.choice(param, Arb.float())
    val commands = arbitrary {
        VehicleCommand(Arb.int(0..65535).bind(), p.bind(), p.bind(), p.bind(), p.bind(), p.bind().toDouble(), p.bind().toDouble(), p.bind())
    }

    "a hand-written COMMAND_LONG is the same frame as the generic encoder's, in MAVLink 1 and 2" {
        checkAll(2000, commands, Arb.int(0..255), Arb.int(0..255), Arb.int(0..255), Arb.int(1..2)) { command, target, confirmation, sequence, version ->
            val generic = encoder.encode(CommandWire.encode(command, target, 1, confirmation), 255, 190, sequence, version)
            val written = encoder.encode(CommandWire.encodeLong(command, target, 1, confirmation), 255, 190, sequence, version)
            written.toList() shouldBe generic.toList()
        }
    }

    "its id is COMMAND_LONG's and its payload the message's full length" {
        val payload = CommandWire.encodeLong(VehicleCommand(400, param1 = 1f), 1, 1)
        payload.messageId shouldBe 76
        payload.length shouldBe 33
    }
})
