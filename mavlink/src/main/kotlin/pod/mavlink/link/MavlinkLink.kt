package pod.mavlink.link

/**
 * A byte pipe to MAVLink peers: a UDP socket (listening or sending to one address), a TCP
 * connection or a serial port ([ByteStreamLink] for the last two). It knows nothing of frames; [pod.mavlink.GroundStation] parses what it receives.
 *
 * @see open
 */
public interface MavlinkLink {
    /** What this link was opened on. */
    public val address: LinkAddress

    /** The local port the link is bound to. */
    public val localPort: Int

    /** Peers that [sendToAll] reaches: every peer heard from when listening, else the remote. */
    public val peers: Collection<LinkPeer>

    /**
     * Receives until the link is closed or the caller is cancelled, calling [onBytes] for every
     * datagram (UDP) or chunk (TCP, serial), one call at a time, in the order they arrived. A UDP link
     * calls it on a receive thread that it shares with other UDP links of the process (no hand-off
     * per datagram), other links on the caller's dispatcher: [onBytes] must not block (it would
     * hold up the links beside it) and must publish what it changes safely for other threads. Throws [LinkException] if the link breaks (a TCP server hanging up); returns
     * normally when [close] was called.
     */
    public suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit)

    /** Sends [bytes] to [peer]. */
    public suspend fun send(bytes: ByteArray, peer: LinkPeer)

    /**
     * Whether [sendNow] works on this link: a UDP or in-memory link writes a datagram without
     * waiting for anything; TCP writes through a suspending channel and says false.
     */
    public val sendsInPlace: Boolean get() = false

    /**
     * Sends [bytes] to [peer] from the calling thread without suspending (a protocol exchange
     * answering on the receive path); only on a link that [sendsInPlace].
     */
    public fun sendNow(bytes: ByteArray, peer: LinkPeer) {
        throw UnsupportedOperationException("$address cannot send in place")
    }

    /** Sends [bytes] to every peer in [peers]. */
    public suspend fun sendToAll(bytes: ByteArray) {
        for (peer in peers) send(bytes, peer)
    }

    /** Closes the socket; [receive] returns. The socket is released a moment later: see [awaitClosed]. */
    public fun close()

    /**
     * Suspends until the socket [close] closed is released, so that its port can be bound again at
     * once (a command run right after another on the same `udpin` port).
     */
    public suspend fun awaitClosed() {}

    /** Opens links from addresses or connection strings. */
    public companion object {
        /**
         * Opens a link on [address]: binds or connects now, so a port in use or an unknown host
         * fails here with [PortInUse] or [HostUnreachable]. A [LinkAddress.Replay] plays its tlog
         * back in real time (a missing file throws [pod.mavlink.tlog.TlogException]). A
         * [LinkAddress.Serial] opens its device now: [DeviceNotFound] or [DeviceUnavailable].
         */
        public suspend fun open(address: LinkAddress): MavlinkLink = when (address) {
            is LinkAddress.UdpIn, is LinkAddress.UdpOut -> UdpLink.open(address)
            is LinkAddress.Tcp -> TcpLink.open(address)
            is LinkAddress.Serial -> SerialLink.open(address)
            is LinkAddress.Replay -> pod.mavlink.tlog.TlogReplayLink.open(java.nio.file.Path.of(address.path))
        }

        /** Parses [connection] (see [LinkAddress.parse]) and opens it. */
        public suspend fun open(connection: String): MavlinkLink = open(LinkAddress.parse(connection))
    }
}

/**
 * One remote end of a link: where datagrams came from and where replies go. Two peers are the
 * same when their [address]es are equal.
 */
public class LinkPeer(
    /** Where the peer is: a socket address for UDP and TCP, any value with equality for other links. */
    public val address: Any,
) {
    override fun equals(other: Any?): Boolean = other is LinkPeer && other.address == address

    override fun hashCode(): Int = address.hashCode()

    override fun toString(): String = address.toString().removePrefix("/")
}
