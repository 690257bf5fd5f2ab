package pod.mavlink.command

import kotlin.time.Duration.Companion.nanoseconds

/** A COMMAND_ACK as the command protocol sees it. */
public data class CommandReply(
    /** The MAV_CMD it answers. */
    public val command: Int,
    /** The raw MAV_RESULT number. */
    public val resultCode: Int,
    /** Progress in percent with IN_PROGRESS, or null when the vehicle did not say (255). */
    public val progress: Int? = null,
    /** Command-specific extra result. */
    public val resultParam2: Int = 0,
) {
    /** The result, or null for a number this dialect does not define. */
    public val result: CommandResult? get() = CommandResult.of(resultCode)
}

/**
 * One command exchange as a pure state machine (no I/O, no clock of its own): [start], then feed
 * it the vehicle's answers to this command and call [onTimer] when [Step.wakeAt] passes. Each step
 * says whether to send the command (and with which `confirmation`), when to wake next, and, at the
 * end, the outcome.
 */
internal class CommandTransaction(
    private val command: VehicleCommand,
    private val timing: CommandTiming,
    private val roundTrip: CommandRoundTrip,
) {
    sealed interface Outcome {
        data class Accepted(val reply: CommandReply) : Outcome
        data class Rejected(val reply: CommandReply) : Outcome
        data class TimedOut(val attempts: Int, val waitedNanos: Long, val waitingFor: String) : Outcome
    }

    /** [confirmation] ≥ 0 means send the command with it; [wakeAt] is absolute, Long.MAX_VALUE for never. */
    data class Step(val confirmation: Int = -1, val wakeAt: Long = Long.MAX_VALUE, val outcome: Outcome? = null)

    private enum class Phase { AWAITING_ACK, RETRY_LATER, IN_PROGRESS, DONE }

    private var phase = Phase.AWAITING_ACK
    private var startedAt = 0L
    private var lastHeardAt = 0L // last send or answer: silence is counted from here
    private var lastSentAt = 0L
    private var attempts = 0
    private var attemptTimeout = 0L
    private var firstRejectedAt = -1L
    private var quickResends = 0
    private var wakeAt = Long.MAX_VALUE

    /** Percent done as the vehicle last reported with IN_PROGRESS, or null. */
    var progress: Int? = null
        private set

    val isDone: Boolean get() = phase == Phase.DONE

    fun start(now: Long): Step {
        startedAt = now
        lastHeardAt = now
        attemptTimeout = roundTrip.attemptTimeoutNanos
        return send(now)
    }

    fun onReply(reply: CommandReply, now: Long): Step {
        if (phase == Phase.DONE || reply.command != command.command) return Step(wakeAt = wakeAt)
        if (attempts == 1 && phase == Phase.AWAITING_ACK) roundTrip.sample(now - lastSentAt)
        lastHeardAt = now
        return when (reply.result) {
            CommandResult.ACCEPTED -> finish(Outcome.Accepted(reply))
            CommandResult.IN_PROGRESS -> {
                phase = Phase.IN_PROGRESS
                progress = reply.progress ?: progress
                wait(now + timing.inProgressTimeout.inWholeNanoseconds)
            }
            CommandResult.TEMPORARILY_REJECTED -> {
                if (firstRejectedAt < 0) firstRejectedAt = now
                if (now - firstRejectedAt + timing.retryDelay.inWholeNanoseconds > timing.temporarilyRejectedFor.inWholeNanoseconds) {
                    finish(Outcome.Rejected(reply))
                } else {
                    phase = Phase.RETRY_LATER
                    wait(now + timing.retryDelay.inWholeNanoseconds)
                }
            }
            else -> finish(Outcome.Rejected(reply))
        }
    }

    /**
     * The timer fired at [now]. [vehicleTalking] says whether the vehicle has been sending other
     * messages (within the last second): then the command or its ack was lost on a live link, and the
     * command goes again after the same short timeout (up to [CommandTiming.quickResends] times);
     * from a silent vehicle the wait grows by half each time.
     */
    fun onTimer(now: Long, vehicleTalking: Boolean = false): Step {
        if (phase == Phase.DONE || now < wakeAt) return Step(wakeAt = wakeAt)
        return when (phase) {
            Phase.IN_PROGRESS -> finish(Outcome.TimedOut(attempts, now - startedAt, "a final result after IN_PROGRESS${progress?.let { " ($it %)" } ?: ""}"))
            Phase.RETRY_LATER -> {
                attemptTimeout = roundTrip.attemptTimeoutNanos
                send(now)
            }
            else -> {
                if (now - lastHeardAt >= timing.timeout.inWholeNanoseconds) {
                    finish(Outcome.TimedOut(attempts, now - startedAt, "COMMAND_ACK"))
                } else {
                    if (vehicleTalking && quickResends < timing.quickResends) {
                        quickResends++
                    } else {
                        attemptTimeout = (attemptTimeout * 3 / 2).coerceAtMost(timing.maxAttemptTimeout.inWholeNanoseconds)
                    }
                    send(now)
                }
            }
        }
    }

    private fun send(now: Long): Step {
        phase = Phase.AWAITING_ACK
        val confirmation = attempts.coerceAtMost(255)
        attempts++
        lastSentAt = now
        // Never sleep past the silence deadline: the command fails on time even with long attempts.
        wakeAt = minOf(now + attemptTimeout, lastHeardAt + timing.timeout.inWholeNanoseconds).coerceAtLeast(now)
        return Step(confirmation = confirmation, wakeAt = wakeAt)
    }

    private fun wait(at: Long): Step {
        wakeAt = at
        return Step(wakeAt = at)
    }

    private fun finish(outcome: Outcome): Step {
        phase = Phase.DONE
        wakeAt = Long.MAX_VALUE
        return Step(outcome = outcome)
    }

    /** The failure [outcome] stands for, as the exception callers see. */
    fun error(outcome: Outcome, statusTexts: List<String>): CommandException? = when (outcome) {
        is Outcome.Accepted -> null
        is Outcome.Rejected -> CommandRejected(command, outcome.reply.result, outcome.reply.resultCode, statusTexts, attempts)
        is Outcome.TimedOut -> CommandTimeout(command, outcome.attempts, outcome.waitedNanos.nanoseconds, outcome.waitingFor)
    }
}
