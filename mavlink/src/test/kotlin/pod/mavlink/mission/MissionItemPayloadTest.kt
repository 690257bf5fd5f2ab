package pod.mavlink.mission

import io.dronefleet.mavlink.common.MissionItemInt
import io.dronefleet.mavlink.common.MissionCurrent
import io.dronefleet.mavlink.common.MissionRequestInt
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.float
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.map
import io.kotest.property.checkAll
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec

internal class MissionItemPayloadTest : FunSpec({
    val encoder = FrameEncoder()
    // Any float bits, NaNs and infinities included: the wire carries them as they are.
    val anyFloat = Arb.int().map { Float.fromBits(it) }
    val items = arbitrary {
        MissionItem(
            seq = Arb.int(0..65535).bind(), frame = Arb.int(0..255).bind(), command = Arb.int(0..65535).bind(),
            current = Arb.boolean().bind(), autocontinue = Arb.boolean().bind(),
            param1 = anyFloat.bind(), param2 = anyFloat.bind(), param3 = Arb.float().bind(), param4 = anyFloat.bind(),
            x = Arb.int().bind(), y = Arb.int().bind(), z = anyFloat.bind(),
            missionType = Arb.element(MissionType.entries).bind(),
        )
    }

    test("a MISSION_ITEM_INT written straight from the item is byte for byte the generic encoder's, MAVLink 1 and 2") {
        checkAll(300, items, Arb.int(0..255), Arb.int(0..255), Arb.int(0..255)) { item, system, component, sequence ->
            val message = MissionMessage.Item(item)
            val direct = MissionWire.encodeToSend(message, system, component)
            val generic = MissionWire.encode(message, system, component)
            for (version in 1..2) {
                encoder.encode(direct, 255, 190, sequence, version).toList() shouldBe encoder.encode(generic, 255, 190, sequence, version).toList()
            }
            // And it reads back as the item it was made from.
            val frames = mutableListOf<MavFrame>()
            FrameDecoder().feed(encoder.encode(direct, 255, 190, sequence)) { frames += it }
            val decoded = MissionWire.decode(MessageCodec.Default.decode(frames.single())!!) as MissionMessage.Item
            decoded.item shouldBe item
        }
    }

    test("only a MISSION_ITEM_INT goes the direct way: the legacy MISSION_ITEM and other messages are built as before") {
        val item = MissionItem(seq = 3, frame = 6, command = 16, x = 1, y = 2)
        (MissionWire.encodeToSend(MissionMessage.Item(item, legacy = true), 1, 1) is MissionItemInt) shouldBe false
        (MissionWire.encodeToSend(MissionMessage.Item(item, legacy = true), 1, 1) is MissionItemPayload) shouldBe false
        (MissionWire.encodeToSend(MissionMessage.Request(MissionType.MISSION, 3), 1, 1) is MissionRequestInt) shouldBe true
    }

    test("the target of a mission message is read without reflection, and messages without one have none") {
        MissionWire.targetSystem(MissionWire.encode(MissionMessage.Request(MissionType.FENCE, 2), 42, 1)) shouldBe 42
        MissionWire.targetSystem(MissionWire.encode(MissionMessage.Item(MissionItem(seq = 0, frame = 0, command = 16)), 7, 1)) shouldBe 7
        MissionWire.targetSystem(MissionCurrent.builder().seq(1).build()) shouldBe null
        MissionWire.targetSystem("not a message") shouldBe null
    }
})
