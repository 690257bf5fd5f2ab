package pod.mavlink.codec

import io.dronefleet.mavlink.common.BatteryStatus
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.GpsRawInt
import io.dronefleet.mavlink.common.MissionCurrent
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavType
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeSameInstanceAs
import java.math.BigInteger

internal class MessageCodecTest : FunSpec({
    val codec = MessageCodec.Default

    test("ids, classes and CRC_EXTRA come from the dialect") {
        codec.messageId(Heartbeat::class.java) shouldBe 0
        codec.crcExtra(0) shouldBe 50
        codec.messageClass(0) shouldBe Heartbeat::class.java
        codec.messageClass(33) shouldBe GlobalPositionInt::class.java
        codec.crcExtra(33) shouldBe 104
        codec.crcExtra(11_000) shouldBeGreaterThan -1 // ardupilotmega's own DEVICE_OP_READ
        codec.crcExtra(0xABCDEF) shouldBe -1
        codec.messageClass(0xABCDEF) shouldBe null
        codec.crcExtra(-1) shouldBe -1
        shouldThrow<IllegalArgumentException> { codec.messageId(String::class.java) }
    }

    test("every message class of the dialect gets a plan whose fields tile the payload") {
        for (messageClass in codec.messageClasses) {
            val plan = codec.planOf(messageClass)
            var offset = 0
            for (field in plan.fields) {
                field.offset shouldBe offset
                offset += field.size
            }
            plan.length shouldBe offset
            plan.fields.dropWhile { !it.extension }.all { it.extension } shouldBe true
        }
    }

    test("HEARTBEAT's fields are in wire order: the uint32 first") {
        codec.planOf(Heartbeat::class.java).fields.map { it.name } shouldBe
            listOf("customMode", "type", "autopilot", "baseMode", "systemStatus", "mavlinkVersion")
        codec.planOf(BatteryStatus::class.java).fields.map { it.kind }.take(4) shouldBe
            listOf(FieldKind.INT, FieldKind.INT, FieldKind.INT, FieldKind.INT_LIST) // int32, int32, int16, uint16[10]
    }

    test("a truncated payload is read zero-extended and an over-long one ignores the extra bytes") {
        val id = codec.messageId(MissionCurrent::class.java)
        val short = codec.decode(MavFrame(2, 0, 1, 1, id, byteArrayOf(7))) as MissionCurrent
        short.seq() shouldBe 7
        short.total() shouldBe 0
        val long = codec.decode(MavFrame(2, 0, 1, 1, id, ByteArray(40) { if (it == 0) 7 else 0 })) as MissionCurrent
        long shouldBe short
        codec.decode(MavFrame(2, 0, 1, 1, id, ByteArray(0))) shouldBe codec.decode(MavFrame(2, 0, 1, 1, id, ByteArray(1)))
    }

    test("uint64 decodes unsigned and int16 signed") {
        val gps = GpsRawInt.builder().timeUsec(BigInteger("18446744073709551615")).alt(-5).build()
        val payload = codec.encodePayload(gps)
        val back = codec.decode(MavFrame(2, 0, 1, 1, 24, payload)) as GpsRawInt
        back.timeUsec() shouldBe BigInteger("18446744073709551615")
        back.alt() shouldBe -5
        val sys = codec.decode(MavFrame(2, 0, 1, 1, 1, ByteArray(31) { if (it == 30) -1 else 0 })) as SysStatus
        sys.batteryRemaining() shouldBe -1
    }

    test("enum values are built once per value and shared between decodes") {
        val heartbeat = Heartbeat.builder().type(MavType.MAV_TYPE_HEXAROTOR).build()
        val frame = MavFrame(2, 0, 1, 1, 0, codec.encodePayload(heartbeat))
        val first = codec.decode(frame) as Heartbeat
        val second = codec.decode(frame) as Heartbeat
        first.type().entry() shouldBe MavType.MAV_TYPE_HEXAROTOR
        second.type() shouldBeSameInstanceAs first.type()
        val table = EnumValueTable(MavType::class.java)
        table.valueOf(100_000).entry() shouldBe null
        table.valueOf(100_000) shouldBeSameInstanceAs table.valueOf(100_000)
        table.valueOf(-3).value() shouldBe -3
    }

    test("null objects in a message encode as zeros") {
        codec.encodePayload(Heartbeat.builder().build()).all { it.toInt() == 0 } shouldBe true
    }
})
