package pod.mavlink.link

import io.ktor.network.sockets.InetSocketAddress
import kotlinx.coroutines.CompletableDeferred
import java.net.SocketAddress
import java.nio.channels.DatagramChannel

/**
 * One [UdpLink.receive] call as a [UdpReceiveLoop] sees it: the channel to read, the handler to
 * call, and how the call ends. Touched by the loop's thread only, apart from [ended].
 */
internal class UdpReceiver(
    val channel: DatagramChannel,
    /** How the link is named in errors. */
    val name: String,
    private val onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit,
    /** Called once per new source address, with the peer made for it. */
    private val onNewPeer: (SocketAddress, LinkPeer) -> Unit,
) {
    // Interning peers keeps one object per address, so callers can key state by peer cheaply.
    private val interned = HashMap<SocketAddress, LinkPeer>()

    /** Why the loop stopped receiving for this link, when it was not the link's closing. */
    var failure: Throwable? = null

    /** Completes when the loop no longer reads the channel (exceptionally with [failure]). */
    val ended = CompletableDeferred<Unit>()

    fun deliver(from: SocketAddress, bytes: ByteArray) {
        val peer = interned.getOrPut(from) { LinkPeer(from.asKtorAddress()).also { onNewPeer(from, it) } }
        onBytes(peer, bytes)
    }
}

// Peers carry Ktor addresses, as every link's peers do (LinkPeer.address); made once per new sender.
private fun SocketAddress.asKtorAddress(): InetSocketAddress {
    val inet = this as java.net.InetSocketAddress
    return InetSocketAddress(inet.address.address, inet.port)
}
