package pod.mavlink.mission

import pod.mavlink.protocol.Outcome
import pod.mavlink.protocol.ProtocolMachine
import pod.mavlink.protocol.Step
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
    private val answer: (MissionMessage) -> Outcome<Unit>?,
) : ProtocolMachine<MissionMessage, MissionMessage, Unit> {
    private val rtt = RoundTripEstimator(timing)

    /** The clock reading of the event being handled: timers are set from it. */
    private var at = 0L

    private fun after(send: List<MissionMessage>): Step<MissionMessage, Nothing> = Step(send, at + rtt.timeoutNanos)
    private var timeouts = 0
    private var sentAt = 0L
    private var ended = false

    override fun start(now: Long): Step<MissionMessage, Unit> {
        at = now
        sentAt = now
        return after(listOf(request))
    }

    override fun onMessage(message: MissionMessage, now: Long): Step<MissionMessage, Unit> {
        if (ended) return Step.NOTHING
        val outcome = answer(message) ?: return Step.NOTHING
        ended = true
        if (timeouts == 0) rtt.sample(now - sentAt)
        return Step(wakeAt = Step.NEVER, outcome = outcome)
    }

    override fun onTimer(now: Long): Step<MissionMessage, Unit> {
        at = now
        if (ended) return Step.NOTHING
        if (++timeouts > timing.retries) {
            ended = true
            return Step(
                wakeAt = Step.NEVER,
                outcome = Outcome.Failed(MissionTimeout(type, timing.retries, rtt.timeoutNanos.nanoseconds, awaited, operation)),
            )
        }
        rtt.backOff()
        return after(listOf(request))
    }

    companion object {
        /** MISSION_CLEAR_ALL for [type], done on MISSION_ACK ACCEPTED, failed on any other result. */
        fun clear(type: MissionType, timing: TransferTiming) = MissionCommand(
            type, MissionMessage.ClearAll(type), "clear", "MISSION_ACK", timing,
        ) { reply ->
            when {
                reply !is MissionMessage.Ack || reply.type != type -> null
                reply.result == MissionResult.ACCEPTED -> Outcome.Done(Unit)
                else -> Outcome.Failed(MissionRejected(type, reply.result, null, "clear"))
            }
        }

        /** MISSION_SET_CURRENT [seq], done when MISSION_CURRENT reports it. */
        fun setCurrent(seq: Int, timing: TransferTiming) = MissionCommand(
            MissionType.MISSION, MissionMessage.SetCurrent(seq), "set-current", "MISSION_CURRENT with seq $seq", timing,
        ) { reply -> if (reply is MissionMessage.Current && reply.seq == seq) Outcome.Done(Unit) else null }
    }
}
