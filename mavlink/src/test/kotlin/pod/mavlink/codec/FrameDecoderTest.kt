package pod.mavlink.codec

import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldEndWith
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.ints.shouldBeLessThan
import io.kotest.matchers.longs.shouldBeGreaterThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import kotlin.random.Random

internal class FrameDecoderTest : FunSpec({
    val codec = MessageCodec.Default
    val encoder = FrameEncoder(codec)

    /** Each frame as its own wire bytes (re-serialised: equal bytes mean equal frames). */
    fun FrameDecoder.collect(chunks: List<ByteArray>): List<String> {
        val frames = mutableListOf<String>()
        for (chunk in chunks) {
            feed(chunk) { frames += encoder.encode(it).toHex() }
            withClue("pending bytes after a feed") { pendingBytes shouldBeLessThan FrameLayout.MAX_FRAME }
        }
        return frames
    }

    fun heartbeat(sequence: Int): ByteArray = encoder.encode(
        Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
            .systemStatus(MavState.MAV_STATE_STANDBY).customMode(4).mavlinkVersion(3).build(),
        systemId = 1, componentId = 1, sequence = sequence,
    )

    test("frames split at random points decode exactly as when fed one per call") {
        checkAll(300, Arb.list(TestFrames.arb, 1..20), Arb.long()) { wires, seed ->
            val oneByOne = FrameDecoder(codec)
            val expected = wires.map { wire -> oneByOne.collect(listOf(wire)).single() }
            expected shouldBe wires.map { it.toHex() }

            val chunked = FrameDecoder(codec)
            chunked.collect(TestFrames.split(wires.concat(), Random(seed))) shouldBe expected
            chunked.stats.frames shouldBe wires.size.toLong()
            chunked.stats.badCrc shouldBe 0
            chunked.stats.skippedBytes shouldBe 0
            chunked.pendingBytes shouldBe 0
        }
    }

    test("a frame fed byte by byte arrives once, with its last byte") {
        val wire = heartbeat(9)
        val decoder = FrameDecoder(codec)
        val arrivals = wire.indices.map { i -> decoder.collect(listOf(byteArrayOf(wire[i]))).size }
        arrivals shouldBe List(wire.size - 1) { 0 } + 1
    }

    test("garbage without magic bytes is skipped and counted, and the frames after it arrive") {
        checkAll(200, Arb.list(TestFrames.arb, 1..5), Arb.int(0..2000), Arb.long()) { wires, garbageSize, seed ->
            val random = Random(seed)
            val decoder = FrameDecoder(codec)
            val frames = decoder.collect(TestFrames.split(TestFrames.clean(random, garbageSize) + wires.concat(), random))
            frames shouldBe wires.map { it.toHex() }
            decoder.stats.skippedBytes shouldBe garbageSize.toLong()
        }
    }

    test("random garbage never throws, keeps the buffer under one frame, and 280 clean bytes resynchronise") {
        checkAll(300, Arb.int(0..3000), Arb.list(TestFrames.arb, 1..4), Arb.long()) { garbageSize, wires, seed ->
            val random = Random(seed)
            val stream = TestFrames.garbage(random, garbageSize) + TestFrames.clean(random, FrameLayout.MAX_FRAME) + wires.concat()
            val decoder = FrameDecoder(codec)
            val chunked = decoder.collect(TestFrames.split(stream, random))
            chunked shouldEndWith wires.map { it.toHex() }
            // Every byte was skipped or delivered in a frame, none twice.
            decoder.stats.skippedBytes + chunked.sumOf { it.length / 2 } shouldBe stream.size.toLong()
            // The parser's output depends on the bytes only, never on how they were cut.
            chunked shouldBe FrameDecoder(codec).collect(listOf(stream))
        }
    }

    test("mutated frames (flipped, cut, dropped or duplicated bytes, stray magic) never throw") {
        checkAll(500, Arb.list(TestFrames.arb, 1..6), Arb.long()) { wires, seed ->
            val random = Random(seed)
            val mutated = wires.map { wire -> if (random.nextBoolean()) mutate(wire, random) else wire }
            val tail = heartbeat(77)
            val stream = mutated.concat() + TestFrames.clean(random, FrameLayout.MAX_FRAME) + tail
            val decoder = FrameDecoder(codec)
            decoder.collect(TestFrames.split(stream, random)) shouldEndWith listOf(tail.toHex())
            decoder.pendingBytes shouldBe 0
        }
    }

    test("a corrupted payload or CRC byte of a known message is counted as a bad CRC and dropped") {
        checkAll(500, Arb.long()) { seed ->
            val random = Random(seed)
            val message = TestMessages.random(gcsMessages.random(random), random)
            val wire = encoder.encode(message, 1, 1, 0)
            val corrupt = wire.copyOf()
            val at = random.nextInt(FrameLayout.HEADER_V2, wire.size) // payload or checksum
            corrupt[at] = (corrupt[at].toInt() xor (1 + random.nextInt(255))).toByte()
            val tail = heartbeat(5)
            val decoder = FrameDecoder(codec)
            val frames = decoder.collect(listOf(corrupt + TestFrames.clean(random, FrameLayout.MAX_FRAME) + tail))
            decoder.stats.badCrc shouldBeGreaterThanOrEqual 1
            frames shouldEndWith listOf(tail.toHex())
            frames.contains(wire.toHex()) shouldBe false
        }
    }

    test("after a bad CRC the parser resumes one byte after the magic and finds the next frame") {
        val first = heartbeat(1)
        first[12] = (first[12] + 1).toByte()
        val second = heartbeat(2)
        val decoder = FrameDecoder(codec)
        decoder.collect(listOf(first + second)) shouldBe listOf(second.toHex())
        decoder.stats.badCrc shouldBe 1
        decoder.stats.skippedBytes shouldBe first.size.toLong()
        decoder.stats.frames shouldBe 1
    }

    test("a valid frame inside the length a false header claims is found after resynchronising") {
        val inner = heartbeat(3)
        // A MAVLink 1 header claiming a 40-byte HEARTBEAT (id 0): its CRC cannot match.
        val falseStart = byteArrayOf(0xFE.toByte(), 40, 0, 1, 1, 0)
        val stream = falseStart + inner + ByteArray(40)
        val decoder = FrameDecoder(codec)
        decoder.collect(listOf(stream)) shouldBe listOf(inner.toHex())
        decoder.stats.badCrc shouldBe 1
        decoder.stats.skippedBytes shouldBe (falseStart.size + 40).toLong()
    }

    test("MAVLink 2 frames with unknown incompatibility flags are skipped") {
        val flagged = heartbeat(4)
        flagged[2] = 0x02
        val crc = Crc.frameChecksum(flagged, 1, flagged.size - 3, codec.crcExtra(0))
        flagged[flagged.size - 2] = crc.toByte()
        flagged[flagged.size - 1] = (crc ushr 8).toByte()
        val next = heartbeat(5)
        val decoder = FrameDecoder(codec)
        decoder.collect(listOf(flagged + next)) shouldBe listOf(next.toHex())
        decoder.stats.badCrc shouldBe 0
        decoder.stats.skippedBytes shouldBe flagged.size.toLong()
    }

    test("frames of unknown message ids pass through unchecked and are counted") {
        val payload = byteArrayOf(1, 2, 3)
        val wire = byteArrayOf(0xFD.toByte(), 3, 0, 0, 9, 42, 7, 0xEF.toByte(), 0xCD.toByte(), 0xAB.toByte()) + payload + byteArrayOf(0x12, 0x34)
        val decoder = FrameDecoder(codec)
        val frames = decoder.decodeAll(wire)
        frames shouldHaveSize 1
        with(frames.single()) {
            messageId shouldBe 0xABCDEF
            sequence shouldBe 9
            systemId shouldBe 42
            componentId shouldBe 7
            this.payload.toList() shouldBe payload.toList()
            codec.decode(this) shouldBe null
        }
        decoder.stats.unknownMessages shouldBe 1
        decoder.stats.frames shouldBe 1
    }

    test("a signed frame passes through with its signature kept") {
        checkAll(100, Arb.long()) { seed ->
            val random = Random(seed)
            val wire = TestFrames.signed(random)
            val frames = mutableListOf<MavFrame>()
            val decoder = FrameDecoder(codec)
            for (chunk in TestFrames.split(wire, random)) decoder.feed(chunk) { frames += it }
            frames shouldHaveSize 1
            val frame = frames.single()
            frame.incompatFlags shouldBe FrameLayout.FLAG_SIGNED
            frame.signature?.toHex() shouldBe wire.copyOfRange(wire.size - 13, wire.size).toHex()
            codec.decode(frame) shouldBe codec.decode(frame.withoutSignature())
            encoder.encode(frame).toHex() shouldBe wire.toHex()
        }
    }

    test("a megabyte of magic-heavy garbage in one feed or byte by byte never throws and accounts for every byte") {
        val garbage = TestFrames.garbage(Random(1), 1 shl 20)
        val whole = FrameDecoder(codec)
        val frames = whole.collect(listOf(garbage))
        whole.stats.frames shouldBe frames.size.toLong()
        // Garbage can only pass as frames of unknown ids, which carry no checkable CRC.
        whole.stats.unknownMessages shouldBe whole.stats.frames
        whole.stats.skippedBytes + frames.sumOf { it.length / 2 } + whole.pendingBytes shouldBe garbage.size.toLong()
        println("1 MiB of garbage (20% magic bytes): ${frames.size} false frames of unknown ids, ${whole.stats.badCrc} bad CRCs")

        val byteByByte = FrameDecoder(codec)
        val slowly = byteByByte.collect(garbage.copyOf(1 shl 16).map { byteArrayOf(it) })
        slowly shouldBe FrameDecoder(codec).collect(listOf(garbage.copyOf(1 shl 16)))
    }

    test("feed reads only the given range") {
        val wire = heartbeat(6)
        val padded = ByteArray(5) { 0xFD.toByte() } + wire + ByteArray(5) { 0xFE.toByte() }
        val decoder = FrameDecoder(codec)
        val frames = mutableListOf<MavFrame>()
        decoder.feed(padded, offset = 5, length = wire.size) { frames += it }
        frames.map { encoder.encode(it).toHex() } shouldBe listOf(wire.toHex())
        decoder.stats.skippedBytes shouldBe 0
        shouldThrow<IndexOutOfBoundsException> { decoder.feed(padded, offset = 5, length = padded.size) {} }
    }

    test("a throwing sink loses the rest of that feed but leaves the decoder usable") {
        val decoder = FrameDecoder(codec)
        shouldThrow<IllegalStateException> { decoder.feed(heartbeat(1) + heartbeat(2)) { error("sink failed") } }
        decoder.pendingBytes shouldBe 0
        decoder.decodeAll(heartbeat(3)).single().sequence shouldBe 3
        decoder.decodeAll(ByteArray(0)).shouldBeEmpty()
    }

    test("decoded frames carry their own payload copies") {
        val decoder = FrameDecoder(codec)
        val input = heartbeat(8)
        val frame = decoder.decodeAll(input).single()
        input.fill(0)
        codec.decode(frame).shouldBeInstanceOf<Heartbeat>().customMode() shouldBe 4
    }
})

private fun MavFrame.withoutSignature(): MavFrame =
    MavFrame(version, sequence, systemId, componentId, messageId, payload)

/** One random corruption of a frame, of the kinds a lossy serial link produces. */
private fun mutate(wire: ByteArray, random: Random): ByteArray {
    val at = random.nextInt(wire.size)
    return when (random.nextInt(6)) {
        0 -> wire.copyOf().also { it[at] = (it[at].toInt() xor (1 + random.nextInt(255))).toByte() }
        1 -> wire.copyOf(at) // truncated
        2 -> wire.copyOfRange(0, at) + wire.copyOfRange(at + 1, wire.size) // one byte lost
        3 -> byteArrayOf(wire[0]) + wire // duplicated magic
        4 -> wire.copyOfRange(0, at) + TestFrames.garbage(random, random.nextInt(1, 20)) + wire.copyOfRange(at, wire.size)
        else -> wire.copyOfRange(0, at) + byteArrayOf(if (random.nextBoolean()) 0xFD.toByte() else 0xFE.toByte()) + wire.copyOfRange(at, wire.size)
    }
}
