package pod.mavlink.param

import pod.mavlink.protocol.Outcome
import pod.mavlink.protocol.Step
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll
import pod.mavlink.command.CommandRoundTrip
import pod.mavlink.command.CommandTiming

class ParamEncodingTest : StringSpec({

    "PX4's bytewise INT32 survives values a float cannot hold exactly; ArduPilot's cast does not pretend to" {
        checkAll(Arb.int()) { n ->
            val wire = ParamEncoding.BYTEWISE.encode(n.toDouble(), ParamType.INT32)
            ParamEncoding.BYTEWISE.decode(wire, ParamType.INT32) shouldBe n.toDouble()
        }
        ParamEncoding.CAST.encode(16_777_217.0, ParamType.INT32) shouldBe 16_777_216f
        ParamEncoding.CAST.decode(5f, ParamType.INT8) shouldBe 5.0
    }

    "bytewise small integer types read only their own bytes, signed or not" {
        ParamEncoding.BYTEWISE.decode(Float.fromBits(0x0000_00FF), ParamType.UINT8) shouldBe 255.0
        ParamEncoding.BYTEWISE.decode(Float.fromBits(0x0000_00FF), ParamType.INT8) shouldBe -1.0
        ParamEncoding.BYTEWISE.decode(Float.fromBits(0x0000_8000), ParamType.INT16) shouldBe -32768.0
        ParamEncoding.BYTEWISE.decode(Float.fromBits(-1), ParamType.UINT32) shouldBe 4_294_967_295.0
        ParamEncoding.BYTEWISE.decode(1.5f, ParamType.REAL32) shouldBe 1.5
    }

    "a write is confirmed by the written value; one stale report is resent, a second different one is a refusal" {
        val timing = CommandTiming()
        val write = ParamExchange("WPNAV_SPEED", 800.0, ParamType.REAL32, timing, CommandRoundTrip(timing))
        write.start(0).send shouldBe listOf(Unit)
        write.onMessage(Parameter("OTHER", 800.0, ParamType.REAL32, 0, 2), 1).send shouldBe emptyList()
        write.onMessage(Parameter("WPNAV_SPEED", 500.0, ParamType.REAL32, 1, 2), 2).send shouldBe listOf(Unit)
        write.onMessage(Parameter("WPNAV_SPEED", 800.0, ParamType.REAL32, 1, 2), 3).outcome
            .shouldBeInstanceOf<Outcome.Done<Parameter>>().value.value shouldBe 800.0

        val refused = ParamExchange("SYSID_SW_TYPE", 3.0, ParamType.INT8, timing, CommandRoundTrip(timing))
        refused.start(0)
        refused.onMessage(Parameter("SYSID_SW_TYPE", 10.0, ParamType.INT8, 0, 1), 1)
        val end = refused.onMessage(Parameter("SYSID_SW_TYPE", 10.0, ParamType.INT8, 0, 1), 2)
        end.outcome.shouldBeInstanceOf<Outcome.Failed>().error.shouldBeInstanceOf<ParamRejected>().message shouldBe "the vehicle kept SYSID_SW_TYPE = 10 instead of 3 (read-only, out of its range, or refused)"
    }

    "a parameter the vehicle does not have times out with a message saying so" {
        val timing = CommandTiming()
        val read = ParamExchange("NO_SUCH", null, null, timing, CommandRoundTrip(timing))
        var step = read.start(0)
        var wakeAt = step.wakeAt
        while (step.outcome == null) {
            step = read.onTimer(wakeAt)
            if (step.wakeAt != Step.KEEP) wakeAt = step.wakeAt
        }
        step.outcome.shouldBeInstanceOf<Outcome.Failed>().error.shouldBeInstanceOf<ParamTimeout>().waited shouldBe timing.timeout
    }
})
