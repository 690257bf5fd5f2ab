package pod.mavlink.route

import io.dronefleet.mavlink.common.MissionRequestInt
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame

/** [FrameTargets]: target_system and target_component read from the payload's bytes, as a decode would give them. */
class FrameTargetsTest : StringSpec({
    val targets = FrameTargets()
    fun frameOf(bytes: ByteArray): MavFrame {
        var frame: MavFrame? = null
        FrameDecoder().feed(bytes) { frame = it }
        return frame!!
    }

    "COMMAND_LONG's targets match the decoded message for any values, MAVLink 2 truncation included" {
        checkAll(Arb.int(0..255), Arb.int(0..255)) { sys, comp ->
            val frame = frameOf(command(255, 190, sys, comp))
            targets.system(frame) shouldBe sys
            targets.component(frame) shouldBe comp
        }
    }

    "a message without target fields has none; an id the dialect does not know has none" {
        targets.system(frameOf(heartbeat(1, 1))) shouldBe FrameTargets.NONE
        targets.component(frameOf(heartbeat(1, 1))) shouldBe FrameTargets.NONE
        val unknown = MavFrame(2, 0, 1, 1, 60_000, byteArrayOf(7, 7, 7))
        targets.system(unknown) shouldBe FrameTargets.NONE
    }

    "MISSION_REQUEST_INT sent as MAVLink 1 carries its targets too" {
        val bytes = FrameEncoder().encode(MissionRequestInt.builder().targetSystem(255).targetComponent(190).seq(3).build(), 1, 1, 0, version = 1)
        val frame = frameOf(bytes)
        targets.system(frame) shouldBe 255
        targets.component(frame) shouldBe 190
    }
})
