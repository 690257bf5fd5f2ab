package pod.mavlink.mission

import kotlin.time.Duration.Companion.nanoseconds

/**
 * A one-message exchange of the mission protocol as a pure state machine: MISSION_CLEAR_ALL
 * answered by MISSION_ACK, or MISSION_SET_CURRENT answered by MISSION_CURRENT. The request is
 * repeated on timeout within the retry budget.
 */
internal class MissionCommand private constructor(
    private val type: MissionType,
    private val request: MissionMessage,
    private val operation: String,
    private val awaited: String,
    private val timing: TransferTiming,
    private val answer: (MissionMessage) -> TransferOutcome<Unit>?,
) {
    private val rtt = RoundTripEstimator(timing)
    private var timeouts = 0
    private var sentAt = 0L
    private var ended = false

    fun start(now: Long): MissionStep<Unit> {
        sentAt = now
        return MissionStep(listOf(request), rtt.timeoutNanos)
    }

    fun onMessage(message: MissionMessage, now: Long): MissionStep<Unit> {
        if (ended) return MissionStep.NOTHING
        val outcome = answer(message) ?: return MissionStep.NOTHING
        ended = true
        if (timeouts == 0) rtt.sample(now - sentAt)
        return MissionStep(timerNanos = MissionStep.NO_TIMER, outcome = outcome)
    }

    fun onTimeout(): MissionStep<Unit> {
        if (ended) return MissionStep.NOTHING
        if (++timeouts > timing.retries) {
            ended = true
            return MissionStep(
                timerNanos = MissionStep.NO_TIMER,
                outcome = TransferOutcome.Failed(MissionTimeout(type, timing.retries, rtt.timeoutNanos.nanoseconds, awaited, operation)),
            )
        }
        rtt.backOff()
        return MissionStep(listOf(request), rtt.timeoutNanos)
    }

    companion object {
        /** MISSION_CLEAR_ALL for [type], done on MISSION_ACK ACCEPTED, failed on any other result. */
        fun clear(type: MissionType, timing: TransferTiming) = MissionCommand(
            type, MissionMessage.ClearAll(type), "clear", "MISSION_ACK", timing,
        ) { reply ->
            when {
                reply !is MissionMessage.Ack || reply.type != type -> null
                reply.result == MissionResult.ACCEPTED -> TransferOutcome.Done(Unit)
                else -> TransferOutcome.Failed(MissionRejected(type, reply.result, null, "clear"))
            }
        }

        /** MISSION_SET_CURRENT [seq], done when MISSION_CURRENT reports it. */
        fun setCurrent(seq: Int, timing: TransferTiming) = MissionCommand(
            MissionType.MISSION, MissionMessage.SetCurrent(seq), "set-current", "MISSION_CURRENT with seq $seq", timing,
        ) { reply -> if (reply is MissionMessage.Current && reply.seq == seq) TransferOutcome.Done(Unit) else null }
    }
}
