package pod.bench.command

import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import java.util.concurrent.atomic.AtomicIntegerArray
import java.util.concurrent.atomic.AtomicLong
import java.util.concurrent.atomic.AtomicLongArray

/**
 * Pod's link with a stopwatch on it: for every vehicle (by system id) the time its COMMAND_LONG
 * was handed to the socket and the time its first COMMAND_ACK reached
 * the station's receive callback, plus how many COMMAND_LONGs went to it. That splits a command's
 * latency into the station's send path, the wire (both sockets and the simulated vehicle), and
 * the station's receive path up to the caller. Costs one `System.nanoTime` per command frame.
 */
class CommandTap(private val inner: MavlinkLink) : MavlinkLink by inner {
    private val sentAt = AtomicLongArray(256)
    private val sendReturnedAt = AtomicLongArray(256)
    private val ackedAt = AtomicLongArray(256)
    private val sends = AtomicIntegerArray(256)
    private val totalSends = AtomicLong()

    /** COMMAND_LONG datagrams sent since the link opened. */
    val commandsSent: Long get() = totalSends.get()

    /** Forgets the previous round. */
    fun resetRound() {
        for (i in 0 until 256) {
            sentAt.set(i, 0)
            sendReturnedAt.set(i, 0)
            ackedAt.set(i, 0)
            sends.set(i, 0)
        }
    }

    /** System.nanoTime when the first COMMAND_LONG of this round to [systemId] left, or 0. */
    fun sentAt(systemId: Int): Long = sentAt.get(systemId)

    /** System.nanoTime when the link's send of that first COMMAND_LONG returned, or 0. */
    fun sendReturnedAt(systemId: Int): Long = sendReturnedAt.get(systemId)

    /** System.nanoTime when the first COMMAND_ACK of this round from [systemId] came in, or 0. */
    fun ackedAt(systemId: Int): Long = ackedAt.get(systemId)

    /** COMMAND_LONGs sent to [systemId] this round. */
    fun sends(systemId: Int): Int = sends.get(systemId)

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        inner.receive { peer, bytes ->
            if (messageId(bytes) == COMMAND_ACK) {
                val system = bytes[5].toInt() and 0xFF
                // An ack before this round's send is a late duplicate from the previous round.
                if (sentAt.get(system) != 0L) ackedAt.compareAndSet(system, 0, System.nanoTime())
            }
            onBytes(peer, bytes)
        }
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) {
        stamped(bytes) { inner.send(bytes, peer) }
    }

    // The station sends in place when the link can (a command's first send and its resends go out
    // from the exchange itself): stamped the same way.
    override fun sendNow(bytes: ByteArray, peer: LinkPeer) {
        stamped(bytes) { inner.sendNow(bytes, peer) }
    }

    private inline fun stamped(bytes: ByteArray, send: () -> Unit) {
        if (messageId(bytes) != COMMAND_LONG) return send()
        // target_system is payload byte 30 (seven floats and the command come first).
        val target = if (bytes.size > 10 + 30) bytes[10 + 30].toInt() and 0xFF else 0
        // Stamped before the send too: on two cores the answer can come in before the send returns.
        val first = sentAt.compareAndSet(target, 0, System.nanoTime())
        sends.incrementAndGet(target)
        totalSends.incrementAndGet()
        send()
        if (first) sendReturnedAt.set(target, System.nanoTime())
    }

    override suspend fun sendToAll(bytes: ByteArray) {
        for (peer in peers) send(bytes, peer)
    }

    private companion object {
        const val COMMAND_LONG = 76
        const val COMMAND_ACK = 77

        /** The message id of a MAVLink 2 frame, or -1. */
        fun messageId(b: ByteArray): Int =
            if (b.size >= 12 && b[0] == 0xFD.toByte()) (b[7].toInt() and 0xFF) or ((b[8].toInt() and 0xFF) shl 8) or ((b[9].toInt() and 0xFF) shl 16) else -1
    }
}
