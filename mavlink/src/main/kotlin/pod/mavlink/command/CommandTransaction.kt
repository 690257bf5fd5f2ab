package pod.mavlink.command

import pod.mavlink.protocol.Outcome
import pod.mavlink.protocol.ProtocolMachine
import pod.mavlink.protocol.Step
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

/** What a [CommandTransaction] reads. */
internal sealed interface CommandInput {
    /** A COMMAND_ACK for this vehicle. */
    data class Reply(val reply: CommandReply) : CommandInput

    /** A line the vehicle sent (joined STATUSTEXT) of warning severity or worse: it may explain a refusal. */
    data class Text(val line: String) : CommandInput

    /** The vehicle's autopilot sent something else: it is alive, so a missing ack was lost. */
    data object Heard : CommandInput
}

/**
 * One command exchange as a pure state machine (no I/O, no clock of its own): each step sends the
 * command (with the `confirmation` number in [Step.send]) or not, says when to wake next, and, at
 * the end, gives the vehicle's reply or the [CommandException] the caller sees.
 *
 * A refusal does not end it at once: ArduPilot answers COMMAND_ACK at once and sends the lines
 * explaining it from its text queue right after (GCS_Common.cpp: GCS_MAVLINK::handle_command_long
 * sends the ack; GCS::send_textv only queues the text, which GCS_MAVLINK::service_statustext sends
 * on the next update_send pass, the same millisecond on SITL). So after a refusal the machine
 * keeps reading [CommandInput.Text] until the vehicle has been quiet for [QUIET_GAP_NANOS], at most
 * [TEXTS_AT_MOST_NANOS]: long enough for a queued line behind the ack on a slow radio, short
 * enough that a refusal without any text is reported at once. Lines sent while the command was
 * pending count too, each once.
 */
internal class CommandTransaction(
    private val command: VehicleCommand,
    private val timing: CommandTiming,
    private val roundTrip: CommandRoundTrip,
    /** How long before [start] the vehicle was last heard (its heartbeat); unknown: never. */
    private val heardBeforeStartNanos: Long = Long.MAX_VALUE / 4,
) : ProtocolMachine<CommandInput, Int, CommandReply> {
    private enum class Phase { AWAITING_ACK, RETRY_LATER, IN_PROGRESS, COLLECTING_TEXTS, DONE }

    private var phase = Phase.AWAITING_ACK
    private var startedAt = 0L
    private var lastHeardAt = 0L // last send or answer: silence is counted from here
    private var vehicleHeardAt = Long.MIN_VALUE / 4 // anything at all from the vehicle
    private var lastSentAt = 0L
    private var attempts = 0
    private var attemptTimeout = 0L
    private var firstRejectedAt = -1L
    private var quickResends = 0
    private var wakeAt = Long.MAX_VALUE
    private val texts = LinkedHashSet<String>()
    private var refusal: CommandReply? = null
    private var refusedAt = 0L

    /** Percent done as the vehicle last reported with IN_PROGRESS, or null. */
    var progress: Int? = null
        private set

    /** How many IN_PROGRESS answers came. */
    var inProgressAnswers: Int = 0
        private set

    val isDone: Boolean get() = phase == Phase.DONE

    override fun start(now: Long): Step<Int, CommandReply> {
        startedAt = now
        lastHeardAt = now
        vehicleHeardAt = now - heardBeforeStartNanos
        attemptTimeout = roundTrip.attemptTimeoutNanos
        return send(now)
    }

    override fun onMessage(message: CommandInput, now: Long): Step<Int, CommandReply> = when (message) {
        is CommandInput.Reply -> onReply(message.reply, now)
        is CommandInput.Text -> onText(message.line, now)
        CommandInput.Heard -> {
            vehicleHeardAt = now
            Step.NOTHING
        }
    }

    fun onReply(reply: CommandReply, now: Long): Step<Int, CommandReply> {
        vehicleHeardAt = now
        if (phase == Phase.DONE || phase == Phase.COLLECTING_TEXTS || reply.command != command.command) return Step.NOTHING
        if (attempts == 1 && phase == Phase.AWAITING_ACK) roundTrip.sample(now - lastSentAt)
        lastHeardAt = now
        return when (reply.result) {
            CommandResult.ACCEPTED -> finish(Outcome.Done(reply))
            CommandResult.IN_PROGRESS -> {
                phase = Phase.IN_PROGRESS
                progress = reply.progress ?: progress
                inProgressAnswers++
                wait(now + timing.inProgressTimeout.inWholeNanoseconds)
            }
            CommandResult.TEMPORARILY_REJECTED -> {
                if (firstRejectedAt < 0) firstRejectedAt = now
                if (now - firstRejectedAt + timing.retryDelay.inWholeNanoseconds > timing.temporarilyRejectedFor.inWholeNanoseconds) {
                    refused(reply, now)
                } else {
                    phase = Phase.RETRY_LATER
                    wait(now + timing.retryDelay.inWholeNanoseconds)
                }
            }
            else -> refused(reply, now)
        }
    }

    private fun onText(line: String, now: Long): Step<Int, CommandReply> {
        if (phase == Phase.DONE) return Step.NOTHING
        // PX4's commander ends the lines it also sends as events with a tab (Commander.cpp:
        // "Mission start denied! No valid mission\t"): with or without it, the same line.
        texts += line.trim()
        if (phase != Phase.COLLECTING_TEXTS) return Step.NOTHING
        return wait(minOf(now + QUIET_GAP_NANOS, refusedAt + TEXTS_AT_MOST_NANOS))
    }

    private fun refused(reply: CommandReply, now: Long): Step<Int, CommandReply> {
        refusal = reply
        refusedAt = now
        phase = Phase.COLLECTING_TEXTS
        return wait(now + QUIET_GAP_NANOS)
    }

    /** The timer fired at [now]; whether the vehicle is talking is judged from the last [CommandInput.Heard]. */
    override fun onTimer(now: Long): Step<Int, CommandReply> = onTimer(now, vehicleTalking = now - vehicleHeardAt < TALKING_WITHIN_NANOS)

    /**
     * The timer fired at [now]. [vehicleTalking] says whether the vehicle has been sending other
     * messages (within the last second): then the command or its ack was lost on a live link, and the
     * command goes again after the same short timeout (up to [CommandTiming.quickResends] times);
     * from a silent vehicle the wait grows by half each time.
     */
    fun onTimer(now: Long, vehicleTalking: Boolean): Step<Int, CommandReply> {
        if (phase == Phase.DONE || now < wakeAt) return Step.NOTHING
        return when (phase) {
            Phase.COLLECTING_TEXTS -> {
                val reply = refusal!!
                finish(Outcome.Failed(CommandRejected(command, reply.result, reply.resultCode, texts.toList(), attempts)))
            }
            Phase.IN_PROGRESS -> timedOut(now, "a final result after IN_PROGRESS${progress?.let { " ($it %)" } ?: ""}")
            Phase.RETRY_LATER -> {
                attemptTimeout = roundTrip.attemptTimeoutNanos
                send(now)
            }
            else -> {
                if (now - lastHeardAt >= timing.timeout.inWholeNanoseconds) {
                    timedOut(now, "COMMAND_ACK")
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

    private fun timedOut(now: Long, waitingFor: String) = finish(Outcome.Failed(CommandTimeout(command, attempts, (now - startedAt).nanoseconds, waitingFor)))

    private fun send(now: Long): Step<Int, CommandReply> {
        phase = Phase.AWAITING_ACK
        val confirmation = attempts.coerceAtMost(255)
        attempts++
        lastSentAt = now
        // Never sleep past the silence deadline: the command fails on time even with long attempts.
        wakeAt = minOf(now + attemptTimeout, lastHeardAt + timing.timeout.inWholeNanoseconds).coerceAtLeast(now)
        return Step(listOf(confirmation), wakeAt)
    }

    private fun wait(at: Long): Step<Int, CommandReply> {
        wakeAt = at
        return Step(wakeAt = at)
    }

    private fun finish(outcome: Outcome<CommandReply>): Step<Int, CommandReply> {
        phase = Phase.DONE
        wakeAt = Long.MAX_VALUE
        return Step(wakeAt = Step.NEVER, outcome = outcome)
    }

    private companion object {
        /** Quiet after the last text before a refusal is reported. */
        const val QUIET_GAP_NANOS = 150_000_000L

        /** Longest wait for texts after a refusal. */
        const val TEXTS_AT_MOST_NANOS = 500_000_000L

        /**
         * A vehicle heard this recently is alive and the command or its ack was lost: resend
         * quickly. Heartbeats alone come once a second; a second is also what telemetry streams
         * at a few Hz leave between messages at 30 % loss only rarely.
         */
        const val TALKING_WITHIN_NANOS = 1_000_000_000L
    }
}

/** How far a command sent with [CommandService.sending] has come. */
public data class CommandProgress(
    /** Percent done as the vehicle last said with IN_PROGRESS (on the last element too), or null when it did not say. */
    public val percent: Int?,
    /** The vehicle's final reply (ACCEPTED), on the last element only; null before. */
    public val reply: CommandReply?,
)
