package pod.mavlink.codec

import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import kotlin.random.Random

/** Random wire frames for decoder tests: messages in both versions, signed frames and unknown ids. */
internal object TestFrames {
    private val codec = MessageCodec.Default
    private val encoder = FrameEncoder(codec)
    private val unknownV1Ids = (0..255).filter { codec.crcExtra(it) < 0 }

    /** Wire bytes of one random frame. */
    fun random(random: Random): ByteArray {
        val version = if (random.nextInt(3) == 0) 1 else 2
        return when (random.nextInt(8)) {
            0 -> unknownId(random, version)
            1 -> signed(random)
            else -> {
                val candidates = if (version == 1) gcsMessages.filter { codec.messageId(it) <= 255 } else gcsMessages
                val message = TestMessages.random(candidates.random(random), random, extensions = version == 2)
                encoder.encode(message, random.nextInt(256), random.nextInt(256), random.nextInt(256), version)
            }
        }
    }

    /** A frame whose message id the dialect does not know, with a random payload. */
    fun unknownId(random: Random, version: Int): ByteArray {
        val id = if (version == 1) unknownV1Ids.random(random) else 0x800000 + random.nextInt(0x7FFFFF)
        return encoder.encode(
            MavFrame(version, random.nextInt(256), random.nextInt(256), random.nextInt(256), id, random.nextBytes(random.nextInt(256))),
        )
    }

    /** A signed MAVLink 2 frame of a known message (the signature is random: decoders keep, not verify, it). */
    fun signed(random: Random): ByteArray {
        val message = TestMessages.random(gcsMessages.random(random), random)
        val plain = FrameDecoder(codec).decodeAll(encoder.encode(message, 1, 1, random.nextInt(256))).single()
        return encoder.encode(
            MavFrame(2, plain.sequence, plain.systemId, plain.componentId, plain.messageId, plain.payload, signature = random.nextBytes(13)),
        )
    }

    val arb: Arb<ByteArray> = arbitrary { rs -> random(rs.random) }

    /** Random bytes in which about one in five is a magic byte, to provoke false frame starts. */
    fun garbage(random: Random, size: Int): ByteArray = ByteArray(size) {
        when (random.nextInt(10)) {
            0 -> 0xFD.toByte()
            1 -> 0xFE.toByte()
            else -> random.nextInt(256).toByte()
        }
    }

    /** Bytes that contain no magic byte: after 280 of them any false frame start has ended. */
    fun clean(random: Random, size: Int): ByteArray = ByteArray(size) { random.nextInt(0xFD).toByte() }

    /** [bytes] cut at random points into pieces (some empty). */
    fun split(bytes: ByteArray, random: Random): List<ByteArray> {
        val cuts = List(random.nextInt(0, 12)) { random.nextInt(bytes.size + 1) }.sorted()
        return (listOf(0) + cuts + bytes.size).zipWithNext { from, to -> bytes.copyOfRange(from, to) }
    }
}

/** Concatenation of byte arrays. */
internal fun List<ByteArray>.concat(): ByteArray {
    val out = ByteArray(sumOf { it.size })
    var at = 0
    for (part in this) {
        part.copyInto(out, at)
        at += part.size
    }
    return out
}
