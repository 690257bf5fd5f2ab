package pod.mavlink.fuzz

import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec
import pod.mavlink.signing.FrameSignature
import pod.mavlink.signing.ReplayGuard
import pod.mavlink.signing.SigningKey
import kotlin.random.Random

/** The receiving side of MAVLink 2 signing under test: whether one received frame is accepted. */
public fun interface SignedReceive {
    /** Whether [frame], received as [wire], is accepted when the receiver's signing time is [now]. */
    public fun accept(frame: MavFrame, wire: ByteArray, now: Long): Boolean
}

/** Pod's signing primitives chained as a receiver chains them: a signed frame, its signature under [key], then a [ReplayGuard]. */
public class SignatureCheck(private val key: SigningKey) : SignedReceive {
    private val guard = ReplayGuard()

    override fun accept(frame: MavFrame, wire: ByteArray, now: Long): Boolean =
        FrameSignature.isSigned(wire) && FrameSignature.verify(wire, key) &&
            guard.accept(frame.systemId, frame.componentId, FrameSignature.linkId(wire), FrameSignature.timestamp(wire), now)
}

/**
 * Signature verification and replay protection behind the datagram decoder: each input is a frame
 * signed with the corpus key — fresh, a minute and more old, replayed, re-signed with another key,
 * or mutated (its signature, link id, timestamp, payload or header) — in a datagram of its own. The
 * receiver ([receive], made from the key: Pod's primitives by default, a station's signed receive
 * path when one exists) must accept exactly the authentic frames the MAVLink signing rules call
 * fresh: a frame signed with the key, unaltered, whose timestamp is above its stream's last accepted
 * one (a new stream's no more than a minute behind the receiver's time). The oracle is that rule,
 * kept here beside the code it checks, as the MAVLink C library applies it (mavlink/c_library_v2,
 * mavlink_helpers.h, `mavlink_signature_check`: the signature first, then a new stream refused when
 * `timestamp + 6000*1000 < signing->timestamp`, a known one when `timestamp <= last`; stream state
 * changes only for a frame that passed). Two things that function also does are not modelled: it
 * refuses new streams beyond MAVLINK_MAX_SIGNING_STREAMS, and it moves its own time up to the
 * newest timestamp accepted.
 */
public class SignedFrameReceive(
    private val corpus: FuzzCorpus,
    override val name: String = "signed",
    receive: (SigningKey) -> SignedReceive = ::SignatureCheck,
    private val codec: MessageCodec = MessageCodec.Default,
) : FuzzTarget {
    private val receiver = receive(corpus.key)
    private val mutator = Mutator(corpus.signed, codec)
    private val encoder = FrameEncoder(codec)
    private val otherKey = SigningKey(ByteArray(SigningKey.SIZE) { (it * 7 + 1).toByte() })
    private val bases = corpus.unsigned.filter { it[0] == 0xFD.toByte() }
    private val corpusSigned = corpus.signed.mapTo(HashSet()) { it.asList() }
    private val recent = ArrayDeque<ByteArray>()
    private val last = HashMap<Int, Long>()

    /** The receiver's signing time: past the corpus's own signed frames by more than a minute, and moving on. */
    private var now = FuzzCorpus.BASE_TIMESTAMP + 10 * ReplayGuard.NEW_STREAM_WINDOW

    override fun runOne(random: Random, tally: FuzzTally) {
        now += random.nextInt(2_000)
        val base = bases[random.nextInt(bases.size)]
        val link = random.nextInt(4)
        val fresh = now - random.nextInt(1_000)
        val genuine = corpus.sign(base, link, if (random.nextInt(8) == 0) now - ReplayGuard.NEW_STREAM_WINDOW - 1 - random.nextInt(1_000_000) else fresh)
        val (mutation, bytes) = when (random.nextInt(6)) {
            0, 1 -> Mutation.NONE to genuine
            2 -> Mutation.NONE to (recent.randomOrNull(random) ?: genuine) // a replay, or a repeat of this frame
            3 -> Mutation.SIGNATURE to mutator.apply(Mutation.SIGNATURE, genuine, random)
            4 -> Mutation.NONE to FrameSignature.sign(genuine.copyOf(), otherKey, link, fresh) // the right frame, the wrong key
            else -> mutator.next(random).let { it.mutation to it.bytes }
        }
        tally.input(mutation, bytes)
        FrameDecoder(codec).feed(bytes) { frame ->
            checkFrame(frame, codec)
            tally.frames++
            val wire = encoder.asWire(frame)
            val accepted = receiver.accept(frame, wire, now)
            val expected = authentic(wire, genuine) && freshFrame(frame, wire)
            property(accepted == expected) {
                if (accepted) "accepted a frame it must refuse (forged, altered, replayed or too old)" else "refused a fresh, authentic frame"
            }
            if (accepted) last[stream(frame, wire)] = FrameSignature.timestamp(wire) else tally.refused++
        }
        // Kept for replays only now: a frame evicted before its replay was fed would look forged.
        if (recent.size == RECENT) recent.removeFirst()
        recent.addLast(genuine)
    }

    /** Signed with the corpus key and not altered since: this input's frame, a recent one, or one of the corpus. */
    private fun authentic(wire: ByteArray, genuine: ByteArray): Boolean =
        wire.contentEquals(genuine) || recent.any { it.contentEquals(wire) } || wire.asList() in corpusSigned

    /** The signing specification's freshness rule, for an authentic frame. */
    private fun freshFrame(frame: MavFrame, wire: ByteArray): Boolean {
        val timestamp = FrameSignature.timestamp(wire)
        val previous = last[stream(frame, wire)]
        return if (previous == null) timestamp >= now - ReplayGuard.NEW_STREAM_WINDOW else timestamp > previous
    }

    private fun stream(frame: MavFrame, wire: ByteArray): Int =
        (frame.systemId shl 16) or (frame.componentId shl 8) or FrameSignature.linkId(wire)

    private companion object {
        /** Frames kept for replaying. */
        const val RECENT = 64
    }
}
