package pod.sim.fault

import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.selects.onTimeout
import kotlinx.coroutines.selects.select
import pod.mavlink.link.MavlinkLink
import java.util.PriorityQueue
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration

/**
 * One direction of a [LossyRelay]: datagrams read from one side go through a [FaultModel] and are
 * written to the other side when their time comes.
 *
 * The socket reader only hands datagrams over ([accept]); one coroutine ([run]) owns the model, the
 * schedule and the clock, so the model needs no lock. Both queues are bounded by [capacity]; what
 * does not fit is counted as discarded, as a router's full queue would drop it.
 */
internal class RelayLeg(
    private val model: FaultModel,
    private val capacity: Int,
    private val clock: () -> Duration,
    private val publish: (LinkCounters) -> Unit,
) {
    private val inbox = Channel<ByteArray>(capacity)
    private val overflowed = AtomicLong()

    /** Deliveries waiting for their time; ties go in the order the model produced them. */
    private val pending = PriorityQueue<Scheduled>(compareBy<Scheduled> { it.delivery.at }.thenBy { it.order })
    private var nextOrder = 0L
    private var forwarded = 0L
    private var unsent = 0L

    private class Scheduled(val delivery: Delivery, val order: Long)

    /** Takes a datagram from the reading socket; never suspends, so a slow leg cannot stall the reader. */
    fun accept(bytes: ByteArray) {
        if (inbox.trySend(bytes).isFailure) overflowed.incrementAndGet()
    }

    /** Forwards to [out] until cancelled. */
    @OptIn(ExperimentalCoroutinesApi::class) // select's onTimeout: a plain withTimeout around receive could lose a datagram
    suspend fun run(out: MavlinkLink) {
        while (true) {
            val now = clock()
            schedule(model.release(now))
            while (true) {
                val head = pending.peek() ?: break
                if (head.delivery.at > now) break
                pending.poll()
                forward(head.delivery.bytes, out)
            }
            publish(counters())
            val wakeAt = listOfNotNull(pending.peek()?.delivery?.at, model.nextRelease).minOrNull()
            val bytes = select<ByteArray?> {
                inbox.onReceive { it }
                if (wakeAt != null) onTimeout(wakeAt - now) { null }
            }
            if (bytes != null) schedule(model.offer(bytes, clock()))
        }
    }

    private fun schedule(deliveries: List<Delivery>) {
        for (delivery in deliveries) {
            if (pending.size >= capacity) unsent++ else pending += Scheduled(delivery, nextOrder++)
        }
    }

    private suspend fun forward(bytes: ByteArray, out: MavlinkLink) {
        // A listening side knows nobody until it has been sent to; until then there is nowhere to go.
        val peers = out.peers
        if (peers.isEmpty()) {
            unsent++
            return
        }
        for (peer in peers) out.send(bytes, peer)
        forwarded++
    }

    private fun counters(): LinkCounters {
        val lost = overflowed.get()
        val model = model.counters
        // Datagrams that overflowed the inbox never reached the model; count them as sent and
        // discarded so that the totals still add up.
        return model.copy(sent = model.sent + lost, delivered = forwarded, discarded = unsent + lost)
    }
}
