package pod.mavlink.link

import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import kotlinx.coroutines.withTimeoutOrNull
import java.io.IOException
import java.util.concurrent.atomic.AtomicLong
import java.util.concurrent.atomic.AtomicReference

/**
 * The one path for links over a byte stream, TCP and serial alike: a single peer, chunks handed
 * to `onBytes` as they arrive (the station's per-peer frame decoder resynchronises after noise and
 * joins frames split across chunks), writes serialized by a mutex so frames never interleave.
 *
 * When the stream goes down, a link without [reopening] (TCP) throws [LinkException] from
 * [receive] and from [send], as a hung-up server is final. A link with it (serial) keeps [receive]
 * running, opens the address again with a bounded backoff until it is back, and meanwhile drops
 * and counts what is sent: a caller is never blocked or thrown at by an unplugged radio. [close]
 * ends the retries at once.
 *
 * @param name how messages name the link ("tcp link to 127.0.0.1:5760").
 * @param endedReason what a stream that ended means ("was closed by the remote").
 */
internal class StreamLink(
    override val address: LinkAddress,
    private val name: String,
    private val endedReason: String,
    first: ByteStream,
    remote: Any,
    override val localPort: Int,
    private val reopening: Reopening?,
) : ByteStreamLink {
    private val peer = LinkPeer(remote)
    private val current = AtomicReference<ByteStream?>(first)
    @Volatile private var lastStream: ByteStream = first
    private val writing = Mutex()
    private val closedSignal = CompletableDeferred<Unit>()
    private val receiveEnded = CompletableDeferred<Unit>()
    private val _state = MutableStateFlow<LinkState>(LinkState.Up)

    @Volatile private var receiveStarted = false
    private val bytesReceived = AtomicLong()
    private val bytesSent = AtomicLong()
    private val outages = AtomicLong()
    private val reopens = AtomicLong()
    private val failedReopens = AtomicLong()
    private val droppedSends = AtomicLong()
    private val droppedBytes = AtomicLong()

    private val closed: Boolean get() = closedSignal.isCompleted

    override val peers: Collection<LinkPeer> = listOf(peer)

    override val state: StateFlow<LinkState> = _state.asStateFlow()

    override val counters: StreamCounters
        get() = StreamCounters(
            bytesReceived.get(), bytesSent.get(), outages.get(), reopens.get(), failedReopens.get(),
            droppedSends.get(), droppedBytes.get(),
        )

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        receiveStarted = true
        try {
            val buffer = ByteArray(CHUNK)
            while (true) {
                val stream = current.get() ?: reopen() ?: return
                val n = try {
                    stream.read(buffer)
                } catch (e: IOException) {
                    if (closed) return
                    wentDown(stream, "broke: ${e.message}", e)
                    continue
                }
                if (n < 0) {
                    if (closed) return
                    wentDown(stream, endedReason, null)
                    continue
                }
                if (n > 0) {
                    bytesReceived.addAndGet(n.toLong())
                    onBytes(peer, buffer.copyOf(n))
                }
            }
        } finally {
            receiveEnded.complete(Unit)
        }
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) {
        if (closed) return
        writing.withLock {
            val stream = current.get()
            if (stream == null) {
                val down = _state.value
                if (reopening == null && down is LinkState.Down) throw LinkException(down.reason)
                dropped(bytes.size)
                return
            }
            val written = try {
                stream.write(bytes)
            } catch (e: IOException) {
                if (closed) return
                dropped(bytes.size)
                wentDown(stream, "broke: ${e.message}", e)
                return
            }
            bytesSent.addAndGet(written.toLong())
            if (written < bytes.size) dropped(bytes.size - written)
        }
    }

    private fun dropped(bytes: Int) {
        droppedSends.incrementAndGet()
        droppedBytes.addAndGet(bytes.toLong())
    }

    /**
     * [stream] failed: the first to notice (the receive loop or a send) closes it and marks the link
     * down; without [reopening] the failure is final and thrown.
     */
    private fun wentDown(stream: ByteStream, reason: String, cause: Throwable?) {
        val error = LinkException("$name $reason", cause)
        if (current.compareAndSet(stream, null)) {
            stream.close()
            outages.incrementAndGet()
            _state.value = LinkState.Down(error.message!!, reopens = reopening != null)
        }
        if (reopening == null) throw error
    }

    /** Opens the address again until it works (the new stream) or the link is closed (null). */
    private suspend fun reopen(): ByteStream? {
        val policy = reopening ?: return null
        var wait = policy.first
        while (true) {
            // Waiting on the close signal, not a plain delay: close() ends the retries at once.
            if (withTimeoutOrNull(wait) { closedSignal.await() } != null) return null
            val stream = try {
                policy.open()
            } catch (e: LinkException) {
                failedReopens.incrementAndGet()
                (_state.value as? LinkState.Down)?.let { _state.compareAndSet(it, it.copy(failedReopens = it.failedReopens + 1)) }
                wait = minOf(wait * 2, policy.longest)
                continue
            }
            current.set(stream)
            lastStream = stream
            if (closed) {
                // close() may have run between the open and the set: the stream is ours to close.
                if (current.compareAndSet(stream, null)) stream.close()
                return null
            }
            reopens.incrementAndGet()
            _state.value = LinkState.Up
            return stream
        }
    }

    override fun close() {
        if (!closedSignal.complete(Unit)) return
        _state.value = LinkState.Closed
        current.getAndSet(null)?.close()
    }

    override suspend fun awaitClosed() {
        lastStream.awaitClosed()
        if (receiveStarted) receiveEnded.await()
    }

    private companion object {
        /** A TCP segment's worth; a serial read returns far less (what arrived within its poll). */
        const val CHUNK = 4096
    }
}
