package pod.mavlink.mission

import pod.mavlink.protocol.Outcome
import pod.mavlink.protocol.ProtocolMachine
import pod.mavlink.protocol.Step
import kotlin.time.Duration.Companion.nanoseconds

/**
 * Ground-station side of a download, as a pure state machine (see [MissionUpload] for the
 * driving contract).
 *
 * MISSION_REQUEST_LIST, then MISSION_COUNT, then the items: up to a window of requests is kept in
 * flight, and on a timeout only the requests still unanswered are repeated. The window grows by one
 * after each window's worth of answers and halves when more than half of it timed out, so a
 * vehicle that drops bursts is soon asked one item at a time.
 *
 * Some vehicles serve requests only in order: PX4 ends the transfer with MISSION_ACK ERROR when
 * asked out of turn; MAVSDK's vehicle-side server silently ignores a request for anything past the
 * item after the last it sent ("sequence incorrect") and drops the whole transfer, silently, after
 * a few repeats or timeouts ("timeout: retries exceeded"; MAVSDK
 * src/mavsdk/core/mavlink_mission_transfer_server.cpp, SendOutgoingMission::process_mission_request_int
 * and process_timeout). Such behaviour is learned from what the vehicle does, not from its
 * autopilot type ([inOrder] is only a starting hint): answers that never come from past a gap
 * while earlier ones do, an ERROR mid-transfer, or a vehicle that falls silent. From then on the
 * vehicle is asked one item at a time, walking on from the first missing item through items
 * already held (so that its own pointer moves on), and when it drops the transfer the download
 * starts over from item 0 with a new MISSION_REQUEST_LIST, within [MAX_RESTARTS]. Ends by sending
 * MISSION_ACK ACCEPTED.
 */
internal class MissionDownload(
    private val type: MissionType,
    private val timing: TransferTiming,
    /** Start as for a vehicle that serves downloads only in order (PX4); otherwise it is learned. */
    inOrder: Boolean = false,
    private val rtt: RoundTripEstimator = RoundTripEstimator(timing),
) : ProtocolMachine<MissionMessage, MissionMessage, List<MissionItem>> {
    /** The clock reading of the event being handled: timers are set from it. */
    private var at = 0L

    private fun after(send: List<MissionMessage>): Step<MissionMessage, Nothing> = Step(send, at + rtt.timeoutNanos)

    private enum class Phase { LISTING, RECEIVING, ENDED }

    private var phase = Phase.LISTING
    private var received: Array<MissionItem?> = emptyArray()
    private var requestedAt = LongArray(0) // 0: not in flight; > 0: first sent at; RETRANSMITTED
    private var inFlight = 0
    private var receivedCount = 0
    private var window = timing.window
    private var answeredSinceResize = 0
    private var timeoutsInARow = 0
    private var inOrder = inOrder
    private var sequentialRetry = inOrder
    private var restarts = 0
    private var cursor = 0 // one-at-a-time mode: the next seq to walk through, had or not
    private var strict = inOrder // restarted walks start at item 0
    private var lowestMissing = 0
    private var aheadSeen = false // an item arrived from past a gap: the vehicle serves out of order

    /** True once the vehicle is known (or was assumed) to serve only in order. */
    val learnedInOrder: Boolean get() = inOrder

    val progress: TransferProgress get() = TransferProgress(receivedCount, received.size)

    override fun start(now: Long): Step<MissionMessage, List<MissionItem>> {
        at = now
        return after(listOf(MissionMessage.RequestList(type)))
    }

    override fun onMessage(message: MissionMessage, now: Long): Step<MissionMessage, List<MissionItem>> {
        at = now
        if (phase == Phase.ENDED) return Step.NOTHING
        return when (message) {
            is MissionMessage.Count -> if (message.type == type && phase == Phase.LISTING) onCount(message.count, now) else Step.NOTHING
            is MissionMessage.Item -> if (message.item.missionType == type && phase == Phase.RECEIVING) onItem(message.item, now) else Step.NOTHING
            is MissionMessage.Ack -> if (message.type == type) onAck(message.result) else Step.NOTHING
            else -> Step.NOTHING
        }
    }

    private var lastProgressAt = Long.MIN_VALUE

    override fun onTimer(now: Long): Step<MissionMessage, List<MissionItem>> {
        at = now
        if (phase == Phase.ENDED) return Step.NOTHING
        if (lastProgressAt == Long.MIN_VALUE) lastProgressAt = now
        timeoutsInARow++
        if (timeoutsInARow > timing.retries && now - lastProgressAt >= timing.patience.inWholeNanoseconds) {
            val waitingFor = if (phase == Phase.LISTING) "the item count" else "item ${received.indexOfFirst { it == null }}"
            return end(Outcome.Failed(MissionTimeout(type, timing.retries, rtt.timeoutNanos.nanoseconds, waitingFor, "download")))
        }
        rtt.backOff()
        if (phase == Phase.LISTING) return after(listOf(MissionMessage.RequestList(type)))
        // A vehicle that stopped answering mid-download may have dropped the transfer (PX4 does after
        // an out-of-turn request whose ERROR we never saw): start it over, one item at a time.
        // Long silence from an in-order vehicle: it has probably dropped the transfer (after an ERROR
        // we never saw); only a new MISSION_REQUEST_LIST revives it. Stateless vehicles never do.
        // Counted in time as well as in timeouts: at 30 % loss, ten short timeouts in a row happen
        // every few hundred items, and a needless restart walks the whole list again.
        if (timeoutsInARow >= timing.retries / 2 && now - lastProgressAt >= timing.patience.inWholeNanoseconds / 4 && restarts < MAX_RESTARTS) {
            // Only a vehicle that dropped the transfer stays silent this long (an ERROR that ended
            // it may have been lost): that is in-order behaviour (PX4, MAVSDK), and a new transfer
            // on the vehicle's side starts at item 0. A stateless vehicle just answers again.
            inOrder = true
            strict = true
            return restart()
        }
        if (!sequentialRetry && inFlight >= 2 && receivedCount > 0 && !aheadSeen) {
            // Answers stop at the first gap and nothing from past it ever came: the vehicle serves
            // only its next item. Walk on one at a time from the gap (the vehicle accepts a request
            // for an item it already sent: MAVSDK does, PX4 for the one just before its next).
            inOrder = true
            sequentialRetry = true
            window = 1
            requestedAt.fill(0L)
            inFlight = 0
            cursor = lowestMissing
            return after(fill(now))
        }
        if (sequentialRetry) {
            if (cursor >= received.size) return after(emptyList())
            requestedAt[cursor] = RETRANSMITTED
            inFlight = 1
            return after(listOf(MissionMessage.Request(type, cursor)))
        }
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
        return after(again + fill(now))
    }

    private fun onCount(count: Int, now: Long): Step<MissionMessage, List<MissionItem>> {
        lastProgressAt = now
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
        return after(fill(now))
    }

    private fun onItem(item: MissionItem, now: Long): Step<MissionMessage, List<MissionItem>> {
        val seq = item.seq
        if (seq !in received.indices) return Step.NOTHING
        if (sequentialRetry && seq == cursor) {
            cursor++
            lastProgressAt = now
            if (requestedAt[seq] > 0L) rtt.sample(now - requestedAt[seq])
            if (requestedAt[seq] != 0L) inFlight--
            requestedAt[seq] = 0L
            timeoutsInARow = 0
            if (received[seq] != null) return after(fill(now))
        } else if (received[seq] != null) {
            return Step.NOTHING // a duplicate
        }
        if (seq > lowestMissing) aheadSeen = true
        if (requestedAt[seq] > 0L) rtt.sample(now - requestedAt[seq])
        if (requestedAt[seq] != 0L) inFlight--
        requestedAt[seq] = 0L
        received[seq] = item
        receivedCount++
        lastProgressAt = now
        while (lowestMissing < received.size && received[lowestMissing] != null) lowestMissing++
        timeoutsInARow = 0
        rtt.progressed()
        if (++answeredSinceResize >= window && window < timing.window) {
            window++
            answeredSinceResize = 0
        }
        if (receivedCount == received.size) return finish()
        return after(fill(now))
    }

    /**
     * Error answers are ambiguous: a vehicle answers stray items of an earlier upload with ERROR,
     * and ArduPilot answers an out-of-range request with INVALID_SEQUENCE. Only an in-order vehicle's
     * ERROR mid-download means this transfer ended; DENIED (busy with another upload) always counts.
     */
    private fun onAck(result: MissionResult): Step<MissionMessage, List<MissionItem>> = when {
        result == MissionResult.ACCEPTED -> Step.NOTHING
        result == MissionResult.DENIED -> end(Outcome.Failed(MissionRejected(type, result, null, "download")))
        // PX4 ends a download it was asked out of turn with ERROR: from now on, in order.
        (inOrder || result == MissionResult.ERROR) && phase == Phase.RECEIVING -> onError(result)
        else -> Step.NOTHING
    }

    private fun onError(result: MissionResult): Step<MissionMessage, List<MissionItem>> {
        if (phase == Phase.RECEIVING && restarts < MAX_RESTARTS) {
            // A vehicle that serves requests only in order (or lost track): start over, one item at a time.
            inOrder = true
            strict = true
            return restart()
        }
        return end(Outcome.Failed(MissionRejected(type, result, received.indexOfFirst { it == null }.takeIf { it >= 0 }, "download")))
    }

    /**
     * Starts over one item at a time, keeping what arrived. Once the vehicle has refused a request
     * out of turn, the walk goes from item 0 again, items already held included, because a vehicle
     * that serves in order (PX4) accepts nothing else; otherwise it resumes at the first gap.
     */
    private fun restart(): Step<MissionMessage, List<MissionItem>> {
        restarts++
        timeoutsInARow = 0 // a fresh streak: the restart itself is the answer to this one
        sequentialRetry = true
        window = 1
        phase = Phase.LISTING
        requestedAt.fill(0L)
        inFlight = 0
        cursor = if (strict) 0 else lowestMissing
        return after(listOf(MissionMessage.RequestList(type)))
    }

    /** Requests for missing items not in flight, lowest first, until the window is full. */
    private fun fill(now: Long): List<MissionMessage> {
        if (sequentialRetry) {
            if (inFlight > 0 || cursor >= received.size) return emptyList()
            requestedAt[cursor] = now.coerceAtLeast(1L)
            inFlight = 1
            return listOf(MissionMessage.Request(type, cursor))
        }
        val max = window
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

    private fun finish(): Step<MissionMessage, List<MissionItem>> {
        phase = Phase.ENDED
        @Suppress("UNCHECKED_CAST")
        val items = (received as Array<MissionItem>).toList()
        return Step(listOf(MissionMessage.Ack(type, MissionResult.ACCEPTED)), Step.NEVER, Outcome.Done(items))
    }

    private fun end(outcome: Outcome<List<MissionItem>>): Step<MissionMessage, List<MissionItem>> {
        phase = Phase.ENDED
        return Step(wakeAt = Step.NEVER, outcome = outcome)
    }

    private companion object {
        const val RETRANSMITTED = -1L

        /**
         * Start-overs allowed. A vehicle that serves only in order, behind a link that reorders,
         * loses track again and again (PX4 over such a link does); better a typed failure than an
         * endless walk.
         */
        const val MAX_RESTARTS = 12
    }
}
