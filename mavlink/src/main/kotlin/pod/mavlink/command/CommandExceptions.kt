package pod.mavlink.command

import pod.core.units.toReadable
import kotlin.time.Duration

/** A command the vehicle did not carry out. */
public sealed class CommandException(message: String) : pod.core.PodException(message) {
    /** The command that was sent. */
    public abstract val command: VehicleCommand
}

/**
 * The vehicle answered [command] with [result] (DENIED, UNSUPPORTED, FAILED, CANCELLED, or
 * TEMPORARILY_REJECTED for longer than the retry budget). [statusTexts] are the STATUSTEXT lines
 * the vehicle sent while the command was pending: ArduPilot explains a refused arm there.
 *
 * When [attempts] is more than 1 the refusal may answer a resend of a command whose first send
 * was carried out and whose acknowledgement was lost: ArduCopter refuses a second takeoff because
 * it is already flying. Check the vehicle's state before concluding it did nothing.
 */
public class CommandRejected(
    override val command: VehicleCommand,
    /** What the vehicle answered; null when it sent a number this dialect does not define. */
    public val result: CommandResult?,
    /** The raw MAV_RESULT number. */
    public val resultCode: Int,
    /** The vehicle's explanation, if it sent one. */
    public val statusTexts: List<String> = emptyList(),
    /** How many times the command had been sent when the refusal came. */
    public val attempts: Int = 1,
    /**
     * What a person can do about it, judged from the vehicle's state when the autopilot gave no
     * reason ("switch with `pod mode GUIDED`"), or null.
     */
    public val hint: String? = null,
) : CommandException(
    "${command.label} was ${result?.name ?: "answered with MAV_RESULT $resultCode"}" +
        (if (statusTexts.isEmpty()) "" else ": " + statusTexts.joinToString("; ")) +
        (hint?.let { " ($it)" } ?: ""),
) {
    internal fun withHint(hint: String?): CommandRejected =
        if (hint == null) this else CommandRejected(command, result, resultCode, statusTexts, attempts, hint)
}

/**
 * No final answer to [command] came within [waited]: no COMMAND_ACK after [attempts] sends, or no
 * final result after the vehicle said IN_PROGRESS.
 */
public class CommandTimeout(
    override val command: VehicleCommand,
    /** How many times the command was sent. */
    public val attempts: Int,
    /** How long Pod waited in all. */
    public val waited: Duration,
    /** What was missing. */
    public val waitingFor: String,
) : CommandException("${command.label} timed out after $attempts sends and ${waited.toReadable()} waiting for $waitingFor")
