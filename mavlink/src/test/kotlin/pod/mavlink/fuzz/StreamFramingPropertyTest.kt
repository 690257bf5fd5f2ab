package pod.mavlink.fuzz

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.byte
import io.kotest.property.arbitrary.byteArray
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.set
import io.kotest.property.checkAll
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec
import pod.mavlink.codec.TestFrames
import pod.mavlink.codec.toHex

/**
 * Serial and TCP framing equals UDP framing: the frames a byte stream yields do not depend on where
 * the stream was cut, and equal what the same frames sent one per datagram yield.
 */
internal class StreamFramingPropertyTest : FunSpec({
    val codec = MessageCodec.Default
    val encoder = FrameEncoder(codec)
    val corpus = FuzzCorpus(seed = 11)

    /** Any valid frame: MAVLink 1 or 2, signed with the corpus key or not (a random signature), known or unknown id. */
    val frames: Arb<ByteArray> = arbitrary { rs ->
        if (rs.random.nextInt(4) == 0) {
            corpus.sign(corpus.unsigned.filter { it[0] == 0xFD.toByte() }.random(rs.random), rs.random.nextInt(256), rs.random.nextLong(1L shl 47))
        } else {
            TestFrames.random(rs.random)
        }
    }

    /** Noise that cannot start a frame: bytes other than the two magic bytes. */
    val cleanNoise: Arb<ByteArray> = Arb.byteArray(Arb.int(0..40), Arb.byte()).let { arb ->
        arbitrary { rs -> arb.bind().filter { it != 0xFD.toByte() && it != 0xFE.toByte() }.toByteArray() }
    }

    /** [stream] cut at [cuts] (taken modulo its length + 1). */
    fun chunks(stream: ByteArray, cuts: Set<Int>): List<ByteArray> {
        val at = (cuts.map { it % (stream.size + 1) } + 0 + stream.size).distinct().sorted()
        return at.zipWithNext { a, b -> stream.copyOfRange(a, b) }
    }

    fun FrameDecoder.frames(chunks: List<ByteArray>): List<String> {
        val out = mutableListOf<String>()
        for (chunk in chunks) feed(chunk) { out += encoder.wireBytes(it).toHex() }
        return out
    }

    test("valid frames with clean noise between them, cut anywhere, yield exactly the frames sent one per datagram") {
        checkAll(400, Arb.list(frames, 1..25), Arb.list(cleanNoise, 25..25), Arb.set(Arb.int(0..1_000_000), 0..60)) { sent, noise, cuts ->
            var stream = ByteArray(0)
            sent.forEachIndexed { i, frame -> stream += noise[i] + frame }
            val perDatagram = FrameDecoder(codec).frames(sent)
            perDatagram shouldBe sent.map { it.toHex() }
            FrameDecoder(codec).frames(chunks(stream, cuts)) shouldBe perDatagram
            FrameDecoder(codec).frames(stream.map { byteArrayOf(it) }) shouldBe perDatagram // a serial port's byte at a time
        }
    }

    test("any bytes at all (frames, mutated frames, magic-heavy noise) frame the same whole and cut anywhere") {
        val mutator = Mutator(corpus.frames)
        val pieces: Arb<ByteArray> = arbitrary { rs -> mutator.next(rs.random).bytes }
        checkAll(400, Arb.list(pieces, 1..20), Arb.set(Arb.int(0..1_000_000), 0..60)) { parts, cuts ->
            val stream = parts.fold(ByteArray(0)) { acc, p -> acc + p }
            val whole = FrameDecoder(codec)
            val cut = FrameDecoder(codec)
            cut.frames(chunks(stream, cuts)) shouldBe whole.frames(listOf(stream))
            listOf(cut.stats.badCrc, cut.stats.skippedBytes, cut.pendingBytes.toLong()) shouldBe
                listOf(whole.stats.badCrc, whole.stats.skippedBytes, whole.pendingBytes.toLong())
        }
    }
})
