package pod.mavlink.command

/** MAV_RESULT: how a vehicle answered a command. */
public enum class CommandResult(
    /** The number on the wire. */
    public val mavValue: Int,
) {
    /** Command is valid and was executed. */
    ACCEPTED(0),

    /** Valid, but cannot be executed right now; retrying later may work. */
    TEMPORARILY_REJECTED(1),

    /** Invalid (wrong parameters, or not allowed in this state); retrying will not help. */
    DENIED(2),

    /** The vehicle does not know or implement this command. */
    UNSUPPORTED(3),

    /** Valid and supported, but executing it failed. */
    FAILED(4),

    /** Being executed; a final result follows. */
    IN_PROGRESS(5),

    /** Cancelled by a later MAV_CMD_REQUEST_OPERATOR_CONTROL-style cancel. */
    CANCELLED(6),

    /** The command only accepts COMMAND_LONG. */
    COMMAND_LONG_ONLY(7),

    /** The command only accepts COMMAND_INT. */
    COMMAND_INT_ONLY(8),

    /** The command's frame is not supported. */
    UNSUPPORTED_FRAME(9),
    ;

    /** Reads results as MAVLink numbers them (MAV_RESULT). */
    public companion object {
        /** The result with number [value], or null for a number this dialect does not define. */
        public fun of(value: Int): CommandResult? = entries.firstOrNull { it.mavValue == value }
    }
}
