package pod.mavlink.route

import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink

/**
 * Several links as one: what is sent to all goes out on every link, what arrives on any is
 * received, and a reply goes back on the link its peer was heard on. A simulated vehicle (or any
 * single-link user) given one sends its telemetry to several ground stations at once and answers
 * whichever commands it, as ArduPilot SITL with several `--out`s does.
 *
 * Bytes from each peer of each link are reassembled into whole frames before they are handed on
 * (a frame decoder per peer, at most [MAX_PEERS] of them), so a receiver with one frame decoder
 * never sees two byte streams interleaved mid-frame; a frame goes on with its original bytes.
 * [receive] hands frames over one call at a time.
 */
public class FanOutLink(
    /** The links, the first of which names this one ([address], [localPort]); at least one. */
    public val links: List<MavlinkLink>,
    private val codec: MessageCodec = MessageCodec.Default,
) : MavlinkLink {
    init {
        require(links.isNotEmpty()) { "a fan-out link needs at least one link" }
    }

    private val encoder = FrameEncoder(codec)
    private val lock = Any()

    // Access order, so the least recently heard peer's decoder is the one dropped past MAX_PEERS.
    private val decoders = object : LinkedHashMap<LinkPeer, FrameDecoder>(16, 0.75f, true) {
        override fun removeEldestEntry(eldest: MutableMap.MutableEntry<LinkPeer, FrameDecoder>) = size > MAX_PEERS
    }

    override val address: LinkAddress get() = links.first().address

    override val localPort: Int get() = links.first().localPort

    override val peers: Collection<LinkPeer>
        get() = links.flatMapIndexed { index, link -> link.peers.map { LinkPeer(Via(index, it)) } }

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit): Unit = coroutineScope {
        links.forEachIndexed { index, link ->
            launch {
                link.receive { inner, bytes ->
                    val peer = LinkPeer(Via(index, inner))
                    synchronized(lock) {
                        decoders.getOrPut(peer) { FrameDecoder(codec) }.feed(bytes) { frame -> onBytes(peer, encoder.wireBytes(frame)) }
                    }
                }
            }
        }
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) {
        val via = peer.address as? Via ?: return
        links.getOrNull(via.link)?.send(bytes, via.peer)
    }

    override val sendsInPlace: Boolean get() = links.all { it.sendsInPlace }

    override fun sendNow(bytes: ByteArray, peer: LinkPeer) {
        val via = peer.address as? Via ?: return
        links.getOrNull(via.link)?.sendNow(bytes, via.peer)
    }

    override suspend fun sendToAll(bytes: ByteArray) {
        for (link in links) link.sendToAll(bytes)
    }

    override fun close() {
        links.forEach { it.close() }
    }

    override suspend fun awaitClosed() {
        for (link in links) link.awaitClosed()
    }

    override fun toString(): String = links.joinToString(" + ", prefix = "fan-out(", postfix = ")") { it.address.toString() }

    /** A peer of the [link]-th link. */
    private data class Via(val link: Int, val peer: LinkPeer) {
        override fun toString(): String = peer.toString()
    }

    /** The bound on what a fan-out link remembers per peer. */
    public companion object {
        /** Peers whose partial frames are kept; past it the least recently heard one's is dropped. */
        public const val MAX_PEERS: Int = 1024
    }
}
