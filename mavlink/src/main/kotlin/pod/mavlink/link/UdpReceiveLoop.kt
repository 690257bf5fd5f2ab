package pod.mavlink.link

import java.io.IOException
import java.net.PortUnreachableException
import java.nio.ByteBuffer
import java.nio.channels.ClosedChannelException
import java.nio.channels.SelectionKey
import java.nio.channels.Selector
import java.util.concurrent.atomic.AtomicInteger

/**
 * One thread and one java.nio [Selector] receiving for many UDP links: each ready channel is read
 * until it is empty (at most [BATCH] datagrams a turn, so that one flooded link cannot starve the
 * others) into one reused direct buffer, and each datagram goes to its link's handler in place,
 * on this thread, as [UdpLink]'s own thread did before. A simulated fleet of 250 vehicles or a
 * router with many links then holds a few threads, not one per socket.
 *
 * The thread starts with the first link [add]ed and ends when the last one has left, so a process
 * with no open UDP link holds none. A link leaves when it is closed ([remove]) or its handler
 * throws; its [UdpReceiver.ended] completes only after the selector has dropped the channel's
 * registration, which is when java.nio really closes a registered channel's socket: the port can
 * be bound again once [UdpReceiver.ended] is complete.
 *
 * Registering and leaving go through queues and [Selector.wakeup]: `register` from another thread
 * would wait for the selector's `select` to return.
 */
internal class UdpReceiveLoop(private val name: String) {
    private val selector: Selector by lazy { Selector.open() }
    private val lock = Any()
    private val arriving = ArrayList<UdpReceiver>() // guarded by lock
    private val leaving = ArrayList<UdpReceiver>() // guarded by lock
    private var running = false // guarded by lock

    /** Links added and not yet ended: what [UdpReceiveLoops] balances on. */
    private val links = AtomicInteger()

    /** How many links receive here now. */
    val load: Int get() = links.get()

    /** Starts receiving for [receiver]; its [UdpReceiver.ended] completes when it leaves. */
    fun add(receiver: UdpReceiver) {
        links.incrementAndGet()
        val start = synchronized(lock) {
            arriving += receiver
            (!running).also { running = true }
        }
        if (start) Thread(::run, name).apply { isDaemon = true }.start() else selector.wakeup()
    }

    /** Stops receiving for [receiver], whose channel was closed (or is left open after a failure). */
    fun remove(receiver: UdpReceiver) {
        synchronized(lock) { leaving += receiver }
        selector.wakeup()
    }

    private fun run() {
        val buffer = ByteBuffer.allocateDirect(MAX_DATAGRAM)
        try {
            while (true) {
                val (arrived, left) = synchronized(lock) {
                    if (arriving.isEmpty() && leaving.isEmpty() && links.get() == 0) {
                        running = false
                        return
                    }
                    val taken = arriving.toList() to leaving.toList()
                    arriving.clear()
                    leaving.clear()
                    taken
                }
                for (receiver in arrived) register(receiver)
                // Leaving channels were deregistered from the selector by the time select returns
                // (it drops cancelled keys first): only then is a closed channel's socket released.
                if (left.isEmpty()) selector.select() else selector.selectNow()
                for (receiver in left) end(receiver)
                val keys = selector.selectedKeys().iterator()
                while (keys.hasNext()) {
                    val key = keys.next()
                    keys.remove()
                    if (key.isValid) drain(key, buffer)
                }
            }
        } catch (e: Throwable) {
            failAll(e)
            throw e
        }
    }

    private fun register(receiver: UdpReceiver) {
        try {
            receiver.channel.register(selector, SelectionKey.OP_READ, receiver)
        } catch (_: ClosedChannelException) {
            end(receiver) // closed before it got here: never registered, so its socket is gone already
        }
    }

    private fun drain(key: SelectionKey, buffer: ByteBuffer) {
        val receiver = key.attachment() as UdpReceiver
        val channel = receiver.channel
        repeat(BATCH) {
            buffer.clear()
            val from = try {
                channel.receive(buffer) ?: return
            } catch (_: ClosedChannelException) {
                return // the link was closed: remove() is on its way
            } catch (_: PortUnreachableException) {
                return@repeat // an ICMP error for an earlier send: that datagram was lost, nothing more
            } catch (e: IOException) {
                if (channel.isOpen) fail(key, receiver, LinkException("udp link on ${receiver.name} broke: ${e.message}", e))
                return
            }
            buffer.flip()
            val bytes = ByteArray(buffer.remaining())
            buffer.get(bytes)
            try {
                receiver.deliver(from, bytes)
            } catch (e: Throwable) {
                fail(key, receiver, e)
                return
            }
        }
    }

    /** [receiver] stops receiving with [cause]; its channel stays open for sends until the link is closed. */
    private fun fail(key: SelectionKey, receiver: UdpReceiver, cause: Throwable) {
        receiver.failure = cause
        key.cancel()
        synchronized(lock) { leaving += receiver }
    }

    private fun end(receiver: UdpReceiver) {
        val failure = receiver.failure
        val ended = if (failure == null) receiver.ended.complete(Unit) else receiver.ended.completeExceptionally(failure)
        if (ended) links.decrementAndGet()
    }

    /** The selector itself broke (it should not): every link here ends with a [LinkException]. */
    private fun failAll(cause: Throwable) {
        val all = synchronized(lock) {
            running = false
            (arriving + leaving).also { arriving.clear(); leaving.clear() }
        } + runCatching { selector.keys().map { it.attachment() as UdpReceiver } }.getOrDefault(emptyList())
        for (receiver in all) {
            receiver.failure = receiver.failure ?: LinkException("udp receive loop $name broke: ${cause.message}", cause)
            end(receiver)
        }
    }

    private companion object {
        /** The largest UDP payload; MAVLink frames are at most 280 bytes, but a datagram may carry several. */
        const val MAX_DATAGRAM = 65_507

        /** Datagrams read from one channel before the others get their turn. */
        const val BATCH = 64
    }
}
