package pod.mavlink.fuzz

import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec
import kotlin.random.Random

/**
 * UDP's decoding: each input is one datagram, fed in one call to the decoder of its peer, which
 * lives on from datagram to datagram as a [pod.mavlink.GroundStation]'s does (a frame cut at a
 * datagram's end is completed by the next); a new peer now and then. Checks: every byte accounted
 * for ([feedAccounted]), every delivered frame sound and its payload decodable ([checkFrame]), and
 * a valid frame wrapped in garbage ([Mutation.EMBED]) found by a fresh decoder.
 */
public class DatagramDecoding(corpus: FuzzCorpus, private val codec: MessageCodec = MessageCodec.Default) : FuzzTarget {
    override val name: String = "datagram"
    private val mutator = Mutator(corpus.frames, codec)
    private val encoder = FrameEncoder(codec)
    private var decoder = FrameDecoder(codec)

    override fun runOne(random: Random, tally: FuzzTally) {
        if (random.nextInt(NEW_PEER_EVERY) == 0) decoder = FrameDecoder(codec)
        val input = mutator.next(random)
        tally.input(input.mutation, input.bytes)
        tally.frames += feedAccounted(decoder, input.bytes, codec).size
        val embedded = input.embedded ?: return
        val found = feedAccounted(FrameDecoder(codec), input.bytes, codec).map { encoder.asWire(it) }
        property(found.any { it.contentEquals(embedded) }) { "the valid frame inside garbage was not found (${found.size} frames)" }
    }

    private companion object {
        const val NEW_PEER_EVERY = 500
    }
}
