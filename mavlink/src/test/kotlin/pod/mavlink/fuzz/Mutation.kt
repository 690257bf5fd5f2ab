package pod.mavlink.fuzz

import pod.mavlink.codec.Crc
import pod.mavlink.codec.MessageCodec
import pod.mavlink.signing.FrameSignature
import kotlin.random.Random

/**
 * The ways a fuzz input is made from valid frames. Each takes one or two corpus frames and a seeded
 * [Random]; the same random state gives the same bytes, so a failing input is replayed from its
 * seed and index alone.
 */
public enum class Mutation {
    /** The frame unchanged. */
    NONE,

    /** One to eight bits flipped anywhere. */
    BIT_FLIP,

    /** One to four bytes overwritten with random values. */
    BYTE_SET,

    /** One to sixteen random bytes inserted at a random place. */
    INSERT,

    /** One to sixteen bytes removed from a random place. */
    DELETE,

    /** Cut short at a random length (possibly empty). */
    TRUNCATE,

    /** The start of one frame joined to the end of another. */
    SPLICE,

    /** The length byte set to a random value. */
    LENGTH,

    /** The magic byte changed (to the other version's, or anything), or a stray magic byte planted. */
    MAGIC,

    /** MAVLink 2 incompatibility or compatibility flags set to random values. */
    FLAGS,

    /** A byte of a signed frame's signature block changed: its link id, timestamp or signature (a bit flip if unsigned). */
    SIGNATURE,

    /** Header or payload bytes changed and the CRC recomputed: a frame that passes its checksum carrying nonsense. */
    RECRC,

    /** Random bytes before and after the frame (garbage with no magic byte, so the frame must still be found). */
    EMBED,

    /** Several frames, some mutated, in one input. */
    CONCAT,

    /** Random bytes only, with magic bytes more frequent than chance. */
    RANDOM,
}

/** Makes mutated inputs out of [frames]. */
public class Mutator(private val frames: List<ByteArray>, private val codec: MessageCodec = MessageCodec.Default) {
    init {
        require(frames.isNotEmpty()) { "frames must not be empty" }
    }

    /** A random mutation of a random frame; [Input.embedded] is the valid frame the input must still yield, if any. */
    public fun next(random: Random): Input {
        val mutation = MUTATIONS[random.nextInt(MUTATIONS.size)]
        val frame = frames[random.nextInt(frames.size)]
        return Input(mutation, apply(mutation, frame, random), embedded = if (mutation == Mutation.EMBED) frame else null)
    }

    /** [mutation] applied to [frame]. */
    public fun apply(mutation: Mutation, frame: ByteArray, random: Random): ByteArray = when (mutation) {
        Mutation.NONE -> frame.copyOf()
        Mutation.BIT_FLIP -> frame.copyOf().also { f ->
            if (f.isNotEmpty()) repeat(1 + random.nextInt(8)) { val at = random.nextInt(f.size); f[at] = (f[at].toInt() xor (1 shl random.nextInt(8))).toByte() }
        }
        Mutation.BYTE_SET -> frame.copyOf().also { f -> if (f.isNotEmpty()) repeat(1 + random.nextInt(4)) { f[random.nextInt(f.size)] = random.nextInt(256).toByte() } }
        Mutation.INSERT -> random.nextInt(frame.size + 1).let { at -> frame.copyOfRange(0, at) + random.nextBytes(1 + random.nextInt(16)) + frame.copyOfRange(at, frame.size) }
        Mutation.DELETE -> {
            val at = random.nextInt(frame.size)
            val count = minOf(1 + random.nextInt(16), frame.size - at)
            frame.copyOfRange(0, at) + frame.copyOfRange(at + count, frame.size)
        }
        Mutation.TRUNCATE -> frame.copyOf(random.nextInt(frame.size))
        Mutation.SPLICE -> {
            val other = frames[random.nextInt(frames.size)]
            frame.copyOf(random.nextInt(frame.size + 1)) + other.copyOfRange(random.nextInt(other.size + 1), other.size)
        }
        Mutation.LENGTH -> frame.copyOf().also { it[1] = random.nextInt(256).toByte() }
        Mutation.MAGIC -> frame.copyOf().also { f ->
            val magic = if (random.nextBoolean()) MAGICS[random.nextInt(2)] else random.nextInt(256).toByte()
            f[if (random.nextBoolean()) 0 else random.nextInt(f.size)] = magic
        }
        Mutation.FLAGS -> frame.copyOf().also { f -> if (f[0] == MAGICS[0]) f[2 + random.nextInt(2)] = random.nextInt(256).toByte() }
        Mutation.RECRC -> recrc(frame, random)
        Mutation.SIGNATURE -> if (FrameSignature.isSigned(frame)) {
            frame.copyOf().also { f ->
                val at = f.size - 13 + random.nextInt(13)
                f[at] = (f[at].toInt() xor (1 + random.nextInt(255))).toByte()
            }
        } else {
            apply(Mutation.BIT_FLIP, frame, random)
        }
        Mutation.EMBED -> cleanGarbage(random, random.nextInt(64)) + frame + cleanGarbage(random, random.nextInt(64))
        Mutation.CONCAT -> {
            var out = ByteArray(0)
            repeat(2 + random.nextInt(6)) {
                val part = frames[random.nextInt(frames.size)]
                out += if (random.nextBoolean()) part else apply(SIMPLE[random.nextInt(SIMPLE.size)], part, random)
            }
            out
        }
        Mutation.RANDOM -> ByteArray(random.nextInt(300)) { if (random.nextInt(8) == 0) MAGICS[random.nextInt(2)] else random.nextInt(256).toByte() }
    }

    /**
     * Random header or payload bytes of a whole unsigned or signed frame, then a correct CRC for the
     * (possibly changed) message id: what a buggy or hostile sender emits, which the framing layer
     * must pass on and every decoder behind it must survive.
     */
    private fun recrc(frame: ByteArray, random: Random): ByteArray {
        val f = frame.copyOf()
        val v2 = f[0] == MAGICS[0]
        val header = if (v2) 10 else 6
        val payload = f[1].toInt() and 0xFF
        if (f.size < header + payload + 2) return f
        repeat(1 + random.nextInt(6)) {
            // Payload bytes mostly; now and then a sequence, system, component or message id byte.
            val at = if (payload > 0 && random.nextInt(5) != 0) header + random.nextInt(payload) else (if (v2) 4 else 2) + random.nextInt(header - (if (v2) 4 else 2))
            f[at] = random.nextInt(256).toByte()
        }
        val id = if (v2) (f[7].toInt() and 0xFF) or ((f[8].toInt() and 0xFF) shl 8) or ((f[9].toInt() and 0xFF) shl 16) else f[5].toInt() and 0xFF
        val crc = Crc.frameChecksum(f, 1, header - 1 + payload, codec.crcExtra(id).coerceAtLeast(0))
        f[header + payload] = crc.toByte()
        f[header + payload + 1] = (crc ushr 8).toByte()
        return f
    }

    /** One mutated input: how it was made, its bytes, and the frame it must still yield (EMBED only). */
    public data class Input(val mutation: Mutation, val bytes: ByteArray, val embedded: ByteArray?)

    public companion object {
        private val MAGICS = byteArrayOf(0xFD.toByte(), 0xFE.toByte())
        private val MUTATIONS = Mutation.entries.toTypedArray()
        private val SIMPLE = arrayOf(Mutation.BIT_FLIP, Mutation.BYTE_SET, Mutation.INSERT, Mutation.DELETE, Mutation.TRUNCATE, Mutation.LENGTH, Mutation.MAGIC)

        /** [size] random bytes none of which is a magic byte: garbage that cannot start a frame. */
        public fun cleanGarbage(random: Random, size: Int): ByteArray = ByteArray(size) {
            var b = random.nextInt(256)
            while (b == 0xFD || b == 0xFE) b = random.nextInt(256)
            b.toByte()
        }
    }
}
