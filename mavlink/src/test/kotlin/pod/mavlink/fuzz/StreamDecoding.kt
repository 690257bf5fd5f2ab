package pod.mavlink.fuzz

import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec
import kotlin.random.Random

/**
 * A byte stream's decoding (TCP, a serial radio): a run of mutated inputs and valid frames with
 * noise between them, fed to one decoder whole and to another in random chunks (often single
 * bytes, as a serial port hands them over). Checks: both deliver the same frames and the same
 * counters (framing does not depend on where the stream was cut), and each accounts for every byte.
 */
public class StreamDecoding(corpus: FuzzCorpus, private val codec: MessageCodec = MessageCodec.Default) : FuzzTarget {
    override val name: String = "stream"
    private val mutator = Mutator(corpus.frames, codec)
    private val frames = corpus.frames
    private val encoder = FrameEncoder(codec)

    override fun runOne(random: Random, tally: FuzzTally) {
        var stream = ByteArray(0)
        repeat(1 + random.nextInt(MAX_PARTS)) {
            stream += when (random.nextInt(3)) {
                0 -> frames[random.nextInt(frames.size)]
                1 -> Mutator.cleanGarbage(random, random.nextInt(24))
                else -> mutator.next(random).bytes
            }
        }
        tally.input(Mutation.CONCAT, stream)
        val whole = FrameDecoder(codec)
        val expected = feedAccounted(whole, stream, codec).map { encoder.asWire(it) }
        val split = FrameDecoder(codec)
        val got = ArrayList<ByteArray>(expected.size)
        var at = 0
        while (at < stream.size) {
            val chunk = minOf(stream.size - at, if (random.nextBoolean()) 1 + random.nextInt(4) else 1 + random.nextInt(stream.size))
            feedAccounted(split, stream, codec, at, chunk).mapTo(got) { encoder.asWire(it) }
            at += chunk
        }
        property(got.size == expected.size && got.indices.all { got[it].contentEquals(expected[it]) }) {
            "split stream gave ${got.size} frames, whole stream ${expected.size}, or different ones"
        }
        property(
            split.stats.badCrc == whole.stats.badCrc && split.stats.skippedBytes == whole.stats.skippedBytes &&
                split.pendingBytes == whole.pendingBytes,
        ) { "counters differ: split ${split.stats.badCrc}/${split.stats.skippedBytes}/${split.pendingBytes}, whole ${whole.stats.badCrc}/${whole.stats.skippedBytes}/${whole.pendingBytes}" }
        tally.frames += got.size
    }

    private companion object {
        const val MAX_PARTS = 8
    }
}
