package pod.mavlink

import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.LinkPeer

/**
 * One [FrameDecoder] per source address, at most [capacity] of them: the receive coroutine asks for
 * a peer's decoder, the station's tracking loop adds up their counters, on another thread.
 *
 * Every source address costs a decoder with its own buffer, so a flood of datagrams from spoofed
 * addresses would grow memory without limit: beyond [capacity] the peer heard least recently is
 * evicted (its counters are kept in the totals, its partial frame is dropped). A peer that is
 * still talking is heard again at once and keeps its place.
 *
 * Both sides take this object's lock; it is held for a map look-up on the receive path and for one
 * pass over at most [capacity] decoders four times a second on the other.
 */
internal class PeerDecoders(private val capacity: Int, private val codec: MessageCodec) {
    init {
        require(capacity >= 1) { "capacity must be ≥ 1, was $capacity" }
    }

    private val lock = Any()
    private val retired = Totals()
    private var evictions = 0L

    // Access order: iteration starts at the peer heard least recently.
    private val decoders = object : LinkedHashMap<LinkPeer, FrameDecoder>(64, 0.75f, true) {
        override fun removeEldestEntry(eldest: MutableMap.MutableEntry<LinkPeer, FrameDecoder>): Boolean {
            if (size <= capacity) return false
            retired.add(eldest.value)
            evictions++
            return true
        }
    }

    // The peer asked for last and its decoder: most datagrams come from the peer of the one before
    // (one vehicle per link, or bursts), which then costs no lock and no hash. Only the receive
    // path calls decoderFor, and a decoder is evicted only inside it, for another peer, which then
    // becomes the last one: the pair never names an evicted decoder.
    private var lastPeer: LinkPeer? = null
    private var lastDecoder: FrameDecoder? = null

    /** The decoder of [peer], made when the peer is new (which may evict the least recent one). */
    fun decoderFor(peer: LinkPeer): FrameDecoder {
        if (peer === lastPeer) return lastDecoder!!
        val decoder = synchronized(lock) { decoders.getOrPut(peer) { FrameDecoder(codec) } }
        lastPeer = peer
        lastDecoder = decoder
        return decoder
    }

    /** How many peers have a decoder now. */
    val size: Int get() = synchronized(lock) { decoders.size }

    /** Counters of every decoder made so far, evicted ones included, and the number of evictions. */
    fun totals(): Totals = synchronized(lock) {
        val sum = Totals()
        sum.addAll(retired)
        for (decoder in decoders.values) sum.add(decoder)
        sum.evictions = evictions
        sum
    }

    /** Added-up decoder counters. */
    class Totals {
        var frames = 0L
        var badCrc = 0L
        var skippedBytes = 0L
        var unknownMessages = 0L
        var evictions = 0L

        fun add(decoder: FrameDecoder) {
            // The counters are written by the receive coroutine while it holds no lock: a total a
            // few frames stale is fine here.
            frames += decoder.stats.frames
            badCrc += decoder.stats.badCrc
            skippedBytes += decoder.stats.skippedBytes
            unknownMessages += decoder.stats.unknownMessages
        }

        fun addAll(other: Totals) {
            frames += other.frames
            badCrc += other.badCrc
            skippedBytes += other.skippedBytes
            unknownMessages += other.unknownMessages
        }
    }
}
