package pod.mavlink.mission

import pod.mavlink.protocol.Outcome
import pod.mavlink.protocol.ProtocolMachine
import pod.mavlink.protocol.Step
import kotlin.time.Duration.Companion.nanoseconds

/**
 * Ground-station side of an upload, as a pure state machine: feed it the vehicle's messages and
 * timer expiries with the driver's clock reading (nanoseconds), send what each [Step] says.
 *
 * The vehicle leads (MISSION_COUNT, then it requests each item); every request is answered with
 * MISSION_ITEM_INT, legacy MISSION_REQUEST included. Requests older than the newest are stale and
 * ignored. When the next request is late the machine does not wait for the vehicle's own
 * re-request timer: it resends the last item and sends the next ones unasked, up to one past the
 * highest it ever sent — whichever was lost (our item, or the vehicle's request, also after the
 * vehicle took an unasked item), the transfer moves on after one timeout. Vehicles
 * answer an unexpected item harmlessly (ArduPilot with a non-final MISSION_ACK INVALID_SEQUENCE,
 * which is ignored here; PX4 silently). If the final MISSION_ACK does not come, the last item is
 * resent (PX4 and Pod's simulator then acknowledge again); when the budget runs out the outcome is
 * [Outcome.Done(UploadEnd.ACK_MISSING)] and the driver finds out what the vehicle holds.
 */
internal class MissionUpload(
    private val type: MissionType,
    private val items: List<MissionItem>,
    private val timing: TransferTiming,
    private val rtt: RoundTripEstimator = RoundTripEstimator(timing),
    /**
     * Null for a whole list (MISSION_COUNT); otherwise the seq of the first of [items] in a partial
     * write (MISSION_WRITE_PARTIAL_LIST, ArduPilot only), which replaces just those items.
     */
    private val partialFrom: Int? = null,
) : ProtocolMachine<MissionMessage, MissionMessage, UploadEnd> {
    private val first = partialFrom ?: 0

    /** The clock reading of the event being handled: timers are set from it. */
    private var at = 0L

    private fun after(send: List<MissionMessage>): Step<MissionMessage, Nothing> = Step(send, at + rtt.timeoutNanos)

    private enum class Phase { COUNTING, SENDING, AWAITING_ACK, ENDED }

    private var phase = Phase.COUNTING
    private var newest = -1 // highest seq the vehicle has requested
    private val firstSentAt = LongArray(items.size) { UNSENT }
    private var timeoutsInARow = 0
    private var lastItemSent = false
    private var errorsAfterLastItem = 0
    private var staleSeq = -1 // a request older than the newest, seen once: a late duplicate, or a restart?
    private var pendingError: MissionResult? = null
    private var pendingErrorAt = 0L

    private var accepted = false
    private var restarts = 0
    private var highestSent = -1

    /** Items the vehicle has confirmed: those before the newest it asked for, or all once it accepted. */
    val progress: TransferProgress
        get() = TransferProgress(if (accepted) items.size else newest.coerceAtLeast(0), items.size)

    override fun start(now: Long): Step<MissionMessage, UploadEnd> {
        at = now
        return after(listOf(opening()))
    }

    private fun opening(): MissionMessage =
        if (partialFrom == null) MissionMessage.Count(type, items.size) else MissionMessage.WritePartial(type, first, first + items.size - 1)

    override fun onMessage(message: MissionMessage, now: Long): Step<MissionMessage, UploadEnd> {
        at = now
        if (phase == Phase.ENDED) return Step.NOTHING
        if ((message is MissionMessage.Request && message.type == type) || (message is MissionMessage.Ack && message.type == type)) lastHeardAt = now
        return when (message) {
            is MissionMessage.Request -> if (message.type == type) onRequest(message.seq - first, now) else Step.NOTHING
            is MissionMessage.Ack -> if (message.type == type) onAck(message.result, now) else Step.NOTHING
            else -> Step.NOTHING
        }
    }

    private var lastProgressAt = Long.MIN_VALUE
    private var lastHeardAt = Long.MIN_VALUE // anything from the vehicle about this list

    override fun onTimer(now: Long): Step<MissionMessage, UploadEnd> {
        at = now
        if (phase == Phase.ENDED) return Step.NOTHING
        if (lastProgressAt == Long.MIN_VALUE) lastProgressAt = now
        timeoutsInARow++
        pendingError?.let { error ->
            // An error answer followed by silence: the vehicle meant it. Silence long enough for the
            // vehicle's own re-request timer (ArduPilot 1 s, PX4 250 ms), or its next request could
            // still be on the way after a loss.
            if (timeoutsInARow >= 2 && now - pendingErrorAt >= ERROR_SILENCE_NANOS) return end(Outcome.Failed(MissionRejected(type, error, newest.takeIf { it >= 0 }?.plus(first), "upload")))
        }
        if (timeoutsInARow > timing.retries && now - lastProgressAt >= timing.patience.inWholeNanoseconds) {
            val waited = rtt.timeoutNanos.nanoseconds
            return end(
                if (phase == Phase.AWAITING_ACK) {
                    Outcome.Done(UploadEnd.ACK_MISSING)
                } else {
                    Outcome.Failed(
                        MissionTimeout(type, timing.retries, waited, if (phase == Phase.COUNTING) "the first item request" else "a request for item ${first + newest + 1}", "upload"),
                    )
                },
            )
        }
        if (phase == Phase.SENDING && timeoutsInARow >= timing.retries / 2 && now - lastProgressAt >= timing.patience.inWholeNanoseconds / 4 && restarts < MAX_RESTARTS) {
            // Long silence mid-upload: the vehicle has probably dropped the transfer (MAVSDK's
            // vehicle side does, silently, after a few timeouts: ReceiveIncomingMission). Start over
            // with the count; ArduPilot restarts for the same sender, PX4 goes on with its requests.
            restarts++
            timeoutsInARow = 0
            lastProgressAt = now
            phase = Phase.COUNTING
            newest = -1
            staleSeq = -1
            pendingError = null
            firstSentAt.fill(RETRANSMITTED)
            return after(listOf(opening()))
        }
        if (phase == Phase.AWAITING_ACK && timeoutsInARow >= 6 && now - maxOf(lastProgressAt, lastHeardAt) >= QUIET_AFTER_LAST_NANOS) {
            // The last item went out again and again and nothing came back: ArduPilot would answer
            // ERROR and PX4 ACCEPTED to a repeat, but MAVSDK's vehicle side has finished and answers
            // nothing (its handlers are gone once it sent the ACK we lost). A download tells.
            return end(Outcome.Done(UploadEnd.ACK_MISSING))
        }
        rtt.backOff()
        val resend = when (phase) {
            Phase.COUNTING -> listOf(opening())
            Phase.SENDING -> probe()
            Phase.AWAITING_ACK -> listOf(item(items.size - 1))
            Phase.ENDED -> emptyList()
        }
        return after(resend)
    }

    /**
     * The items the vehicle may be waiting for after a late request, in order: from the newest it
     * asked for up to one past the highest we ever sent. The vehicle may have taken items we sent
     * unasked and be waiting (on its own 1 s or 250 ms timer) for one we have not sent yet, its
     * request lost; sent in order, the burst lets it take every item from the one it expects on.
     */
    private fun probe(): List<MissionMessage> {
        val last = minOf(highestSent + 1, items.size - 1, newest + MAX_PROBE - 1)
        return (newest..last).map { seq ->
            firstSentAt[seq] = RETRANSMITTED
            item(seq)
        }
    }

    /** [seq] counts from the first item of this transfer (its index in [items]). */
    private fun onRequest(seq: Int, now: Long): Step<MissionMessage, UploadEnd> {
        if (seq !in items.indices) return Step.NOTHING
        if (seq < newest) {
            // The vehicle is alive and in the upload, whatever it asks.
            timeoutsInARow = 0
            // Once: a late duplicate, answered (cheap, harmless). Twice, or item 0: the vehicle
            // restarted the transfer there (ArduPilot does on a duplicated MISSION_COUNT), so
            // follow it back.
            if (seq != staleSeq && seq != 0) {
                staleSeq = seq
                return Step(listOf(item(seq)))
            }
            newest = seq
            staleSeq = -1
            timeoutsInARow = 0
            phase = Phase.SENDING
            return after(listOf(item(seq)))
        }
        if (seq > newest) {
            pendingError = null
            staleSeq = -1
            // Karn: only a request answering an item sent once measures the round trip.
            if (newest >= 0 && seq == newest + 1 && firstSentAt[newest] >= 0) rtt.sample(now - firstSentAt[newest], mayBeVehicleTimer = true)
            rtt.progressed()
            timeoutsInARow = 0
            lastProgressAt = now
            newest = seq
        }
        firstSentAt[seq] = if (firstSentAt[seq] == UNSENT) now else RETRANSMITTED
        phase = if (seq == items.size - 1) Phase.AWAITING_ACK else Phase.SENDING
        return after(listOf(item(seq)))
    }

    private fun onAck(result: MissionResult, now: Long): Step<MissionMessage, UploadEnd> = when {
        // A stale ACCEPTED (from an earlier transfer) must not pass for this one: only once the
        // last item has gone out (asked for, or sent unasked after a lost request) can it be ours.
        result == MissionResult.ACCEPTED && (items.isEmpty() || lastItemSent) -> {
            accepted = true
            end(Outcome.Done(UploadEnd.ACKNOWLEDGED))
        }
        result == MissionResult.ACCEPTED -> Step.NOTHING
        // ArduPilot's answer to an unexpected item; the transfer goes on.
        result == MissionResult.INVALID_SEQUENCE -> Step.NOTHING
        // Once the last item is out, ERROR is what ArduPilot and PX4 answer to a late or repeated
        // item after they completed the upload: the outcome is unknown, not failed.
        // Ask once more (PX4 and Pod's simulator acknowledge a repeated last item again); ArduPilot
        // keeps answering ERROR, and then only a download can tell.
        result == MissionResult.ERROR && lastItemSent -> if (++errorsAfterLastItem >= 3) {
            end(Outcome.Done(UploadEnd.ACK_MISSING))
        } else {
            phase = Phase.AWAITING_ACK
            Step(listOf(item(items.size - 1)))
        }
        // PX4 answers a duplicated MISSION_COUNT with ERROR ("busy") and carries on, and a vehicle
        // answers a late duplicate of the previous upload's last item with ERROR, which can reach
        // us while this upload is still counting: an ERROR only counts if the vehicle then falls
        // silent (see onTimer).
        result == MissionResult.ERROR -> pending(result, now)
        // ArduPilot answers a repeated MISSION_WRITE_PARTIAL_LIST (ours, resent or duplicated on the
        // way) with DENIED while it serves the first one: only silence afterwards makes it count.
        result == MissionResult.DENIED && partialFrom != null -> pending(result, now)
        else -> end(Outcome.Failed(MissionRejected(type, result, newest.takeIf { it >= 0 }?.plus(first), "upload")))
    }

    private fun pending(error: MissionResult, now: Long): Step<MissionMessage, UploadEnd> {
        if (pendingError == null) pendingErrorAt = now
        pendingError = error
        return Step.NOTHING
    }

    private fun end(outcome: Outcome<UploadEnd>): Step<MissionMessage, UploadEnd> {
        phase = Phase.ENDED
        return Step(wakeAt = Step.NEVER, outcome = outcome)
    }

    private fun item(seq: Int): MissionMessage.Item {
        if (seq == items.size - 1) lastItemSent = true
        if (seq > highestSent) highestSent = seq
        return MissionMessage.Item(items[seq])
    }

    private companion object {
        const val UNSENT = -1L
        const val RETRANSMITTED = -2L

        /** Most items one late request makes us send: enough to catch up with a vehicle ahead, no flood. */
        const val MAX_PROBE = 8

        /** Silence after the last item before its lost ACK is looked for with a download. */
        const val QUIET_AFTER_LAST_NANOS = 2_000_000_000L

        /** Start-overs after the vehicle fell silent mid-upload. */
        const val MAX_RESTARTS = 6

        /** Silence after an ambiguous error answer before it counts: past ArduPilot's 1 s re-request. */
        const val ERROR_SILENCE_NANOS = 1_500_000_000L
    }
}

/** How an upload ended when it did not fail. */
internal enum class UploadEnd {
    /** The vehicle acknowledged the list with MISSION_ACK ACCEPTED. */
    ACKNOWLEDGED,

    /** Every item went out but the final MISSION_ACK never came: only a download can tell what the vehicle holds. */
    ACK_MISSING,
}
