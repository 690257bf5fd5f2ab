package pod.mavlink.codec

import io.dronefleet.mavlink.common.SetupSigning
import io.dronefleet.mavlink.common.Statustext
import io.dronefleet.mavlink.minimal.Heartbeat
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain

internal class FrameEncoderTest : FunSpec({
    val codec = MessageCodec.Default
    val encoder = FrameEncoder(codec)

    test("MAVLink 1 refuses message ids above 255") {
        val message = SetupSigning.builder().targetSystem(1).build()
        codec.messageId(SetupSigning::class.java) shouldBe 256
        shouldThrow<IllegalArgumentException> { encoder.encode(message, 1, 1, 0, version = 1) }.message shouldContain "256"
        shouldThrow<IllegalArgumentException> { encoder.encode(MavFrame(1, 0, 1, 1, 256, ByteArray(3))) }
        encoder.encode(message, 1, 1, 0, version = 2)[7] shouldBe 0 // low byte of id 256
    }

    test("an all-zero message keeps one payload byte in MAVLink 2") {
        val wire = encoder.encode(Heartbeat.builder().build(), 1, 1, 0)
        wire[1] shouldBe 1
        wire.size shouldBe 10 + 1 + 2
    }

    test("out-of-range header values and versions are rejected") {
        val heartbeat = Heartbeat.builder().build()
        shouldThrow<IllegalArgumentException> { encoder.encode(heartbeat, 256, 1, 0) }.message shouldContain "systemId"
        shouldThrow<IllegalArgumentException> { encoder.encode(heartbeat, 1, -1, 0) }.message shouldContain "componentId"
        shouldThrow<IllegalArgumentException> { encoder.encode(heartbeat, 1, 1, 256) }.message shouldContain "sequence"
        shouldThrow<IllegalArgumentException> { encoder.encode(heartbeat, 1, 1, 0, version = 3) }
        shouldThrow<IllegalArgumentException> { encoder.encode("not a message", 1, 1, 0) }
        shouldThrow<IllegalArgumentException> { encoder.encode(MavFrame(2, 0, 1, 1, 0, ByteArray(256))) }
        shouldThrow<IllegalArgumentException> { encoder.encode(MavFrame(2, 0, 1, 1, 0, ByteArray(9), signature = ByteArray(12))) }
        shouldThrow<IllegalArgumentException> { encoder.encode(MavFrame(1, 0, 1, 1, 0, ByteArray(9), signature = ByteArray(13))) }
    }

    test("a raw frame is written as given, with the CRC recomputed from the codec's CRC_EXTRA") {
        val payload = byteArrayOf(4, 0, 0, 0, 2, 3, 81, 4) // a truncated HEARTBEAT payload
        val wire = encoder.encode(MavFrame(2, 17, 1, 1, 0, payload, compatFlags = 0x80))
        wire.copyOfRange(0, 10).toHex() shouldBe "fd080080110101000000"
        wire.copyOfRange(10, 18).toHex() shouldBe payload.toHex()
        val crc = Crc.frameChecksum(wire, 1, 9 + payload.size, 50)
        wire.copyOfRange(18, 20).toHex() shouldBe byteArrayOf(crc.toByte(), (crc ushr 8).toByte()).toHex()
        FrameDecoder(codec).decodeAll(wire).single().compatFlags shouldBe 0x80
    }

    test("frames of unknown ids get CRC_EXTRA 0, and the signed flag follows the signature") {
        val signature = ByteArray(13) { it.toByte() }
        val wire = encoder.encode(MavFrame(2, 0, 1, 1, 0xABCDEF, byteArrayOf(9, 8), incompatFlags = 0, signature = signature))
        wire[2] shouldBe 1
        val crc = Crc.frameChecksum(wire, 1, 9 + 2, 0)
        (wire[12].toInt() and 0xFF) or ((wire[13].toInt() and 0xFF) shl 8) shouldBe crc
        wire.copyOfRange(14, 27).toHex() shouldBe signature.toHex()

        val unsigned = encoder.encode(MavFrame(2, 0, 1, 1, 0xABCDEF, byteArrayOf(9, 8), incompatFlags = 1))
        unsigned[2] shouldBe 0
        unsigned.size shouldBe 14
    }

    test("strings longer than their field are cut to it, arrays too long are refused") {
        val long = "x".repeat(60)
        val wire = encoder.encode(Statustext.builder().severity(io.dronefleet.mavlink.common.MavSeverity.MAV_SEVERITY_INFO).text(long).build(), 1, 1, 0)
        val decoded = codec.decode(FrameDecoder(codec).decodeAll(wire).single()) as Statustext
        decoded.text() shouldBe "x".repeat(50)

        val tooMany = SetupSigning.builder().secretKey(ByteArray(33)).build()
        shouldThrow<IllegalArgumentException> { codec.encodePayload(tooMany) }.message shouldContain "secretKey"
    }
})
