package pod.mavlink.mission

import kotlin.time.Duration.Companion.nanoseconds

/**
 * Ground-station side of a download, as a pure state machine (see [MissionUpload] for the
 * driving contract).
 *
 * MISSION_REQUEST_LIST, then MISSION_COUNT, then the items: up to a window of requests is kept in
 * flight, and on a timeout only the requests still unanswered are repeated. The window grows by one
 * after each window's worth of answers and halves when more than half of it timed out, so a
 * vehicle that drops bursts is soon asked one item at a time. A vehicle that only serves requests
 * in order (PX4 ends the transfer with MISSION_ACK ERROR when asked out of turn) is asked again from
 * the start, one item at a time. Ends by sending MISSION_ACK ACCEPTED.
 */
internal class MissionDownload(
    private val type: MissionType,
    private val timing: TransferTiming,
) {
    private enum class Phase { LISTING, RECEIVING, ENDED }

    private val rtt = RoundTripEstimator(timing)
    private var phase = Phase.LISTING
    private var received: Array<MissionItem?> = emptyArray()
    private var requestedAt = LongArray(0) // 0: not in flight; > 0: first sent at; RETRANSMITTED
    private var inFlight = 0
    private var receivedCount = 0
    private var window = timing.window
    private var answeredSinceResize = 0
    private var timeoutsInARow = 0
    private var sequentialRetry = false
    private var restarts = 0
    private var lowestMissing = 0

    val progress: TransferProgress get() = TransferProgress(receivedCount, received.size)

    fun start(): MissionStep<List<MissionItem>> = MissionStep(listOf(MissionMessage.RequestList(type)), rtt.timeoutNanos)

    fun onMessage(message: MissionMessage, now: Long): MissionStep<List<MissionItem>> {
        if (phase == Phase.ENDED) return MissionStep.NOTHING
        return when (message) {
            is MissionMessage.Count -> if (message.type == type && phase == Phase.LISTING) onCount(message.count, now) else MissionStep.NOTHING
            is MissionMessage.Item -> if (message.item.missionType == type && phase == Phase.RECEIVING) onItem(message.item, now) else MissionStep.NOTHING
            is MissionMessage.Ack -> if (message.type == type && message.result != MissionResult.ACCEPTED) onError(message.result) else MissionStep.NOTHING
            else -> MissionStep.NOTHING
        }
    }

    fun onTimeout(now: Long): MissionStep<List<MissionItem>> {
        if (phase == Phase.ENDED) return MissionStep.NOTHING
        timeoutsInARow++
        if (timeoutsInARow > timing.retries) {
            val waitingFor = if (phase == Phase.LISTING) "the item count" else "item ${received.indexOfFirst { it == null }}"
            return end(TransferOutcome.Failed(MissionTimeout(type, timing.retries, rtt.timeoutNanos.nanoseconds, waitingFor, "download")))
        }
        rtt.backOff()
        if (phase == Phase.LISTING) return MissionStep(listOf(MissionMessage.RequestList(type)), rtt.timeoutNanos)
        // Everything in flight is overdue (the timer runs for the oldest request). Shrink the window
        // when most of it was lost, then ask again for what is missing, in order.
        if (inFlight * 2 > window) window = (window / 2).coerceAtLeast(1)
        answeredSinceResize = 0
        val again = ArrayList<MissionMessage>()
        for (seq in lowestMissing until received.size) {
            if (requestedAt[seq] != 0L && received[seq] == null) {
                if (again.size < window) {
                    requestedAt[seq] = RETRANSMITTED
                    again += MissionMessage.Request(type, seq)
                } else {
                    requestedAt[seq] = 0L
                    inFlight--
                }
            }
        }
        return MissionStep(again + fill(now), rtt.timeoutNanos)
    }

    private fun onCount(count: Int, now: Long): MissionStep<List<MissionItem>> {
        rtt.progressed()
        timeoutsInARow = 0
        if (count == 0) return finish()
        if (received.size != count) {
            received = arrayOfNulls(count)
            requestedAt = LongArray(count)
            receivedCount = 0
            lowestMissing = 0
        }
        phase = Phase.RECEIVING
        inFlight = 0
        requestedAt.fill(0L)
        return MissionStep(fill(now), rtt.timeoutNanos)
    }

    private fun onItem(item: MissionItem, now: Long): MissionStep<List<MissionItem>> {
        val seq = item.seq
        if (seq !in received.indices || received[seq] != null) return MissionStep.NOTHING // duplicate or nonsense
        if (requestedAt[seq] > 0L) rtt.sample(now - requestedAt[seq])
        if (requestedAt[seq] != 0L) inFlight--
        requestedAt[seq] = 0L
        received[seq] = item
        receivedCount++
        while (lowestMissing < received.size && received[lowestMissing] != null) lowestMissing++
        timeoutsInARow = 0
        rtt.progressed()
        if (++answeredSinceResize >= window && window < timing.window) {
            window++
            answeredSinceResize = 0
        }
        if (receivedCount == received.size) return finish()
        return MissionStep(fill(now), rtt.timeoutNanos)
    }

    private fun onError(result: MissionResult): MissionStep<List<MissionItem>> {
        if (phase == Phase.RECEIVING && restarts++ < timing.retries) {
            // A vehicle that serves requests only in order (or lost track): start over, one item at a time.
            sequentialRetry = true
            window = 1
            phase = Phase.LISTING
            received = emptyArray()
            requestedAt = LongArray(0)
            inFlight = 0
            receivedCount = 0
            lowestMissing = 0
            return MissionStep(listOf(MissionMessage.RequestList(type)), rtt.timeoutNanos)
        }
        return end(TransferOutcome.Failed(MissionRejected(type, result, received.indexOfFirst { it == null }.takeIf { it >= 0 }, "download")))
    }

    /** Requests for missing items not in flight, lowest first, until the window is full. */
    private fun fill(now: Long): List<MissionMessage> {
        val max = if (sequentialRetry) 1 else window
        val requests = ArrayList<MissionMessage>()
        var seq = lowestMissing
        while (inFlight < max && seq < received.size) {
            if (received[seq] == null && requestedAt[seq] == 0L) {
                requestedAt[seq] = now.coerceAtLeast(1L)
                inFlight++
                requests += MissionMessage.Request(type, seq)
            }
            seq++
        }
        return requests
    }

    private fun finish(): MissionStep<List<MissionItem>> {
        phase = Phase.ENDED
        @Suppress("UNCHECKED_CAST")
        val items = (received as Array<MissionItem>).toList()
        return MissionStep(listOf(MissionMessage.Ack(type, MissionResult.ACCEPTED)), MissionStep.NO_TIMER, TransferOutcome.Done(items))
    }

    private fun end(outcome: TransferOutcome<List<MissionItem>>): MissionStep<List<MissionItem>> {
        phase = Phase.ENDED
        return MissionStep(timerNanos = MissionStep.NO_TIMER, outcome = outcome)
    }

    private companion object {
        const val RETRANSMITTED = -1L
    }
}
