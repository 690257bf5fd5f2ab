package pod.mavlink.command

/**
 * A MAV_CMD to send to a vehicle. Without a [frame] it travels as COMMAND_LONG with [param5] to
 * [param7] as floats. With a [frame] it travels as COMMAND_INT: for the global frames [param5] and
 * [param6] are latitude and longitude in degrees (sent as degrees × 10⁷ integers, which keeps
 * centimetre precision a float loses) and [param7] is the altitude in that frame.
 */
public data class VehicleCommand(
    /** The MAV_CMD number. */
    public val command: Int,
    /** Parameter 1. */
    public val param1: Float = 0f,
    /** Parameter 2. */
    public val param2: Float = 0f,
    /** Parameter 3. */
    public val param3: Float = 0f,
    /** Parameter 4. */
    public val param4: Float = 0f,
    /** Parameter 5 (x; latitude in degrees with a global [frame]). */
    public val param5: Double = 0.0,
    /** Parameter 6 (y; longitude in degrees with a global [frame]). */
    public val param6: Double = 0.0,
    /** Parameter 7 (z; altitude with a [frame]). */
    public val param7: Float = 0f,
    /** MAV_FRAME number to send this as COMMAND_INT, or null for COMMAND_LONG. */
    public val frame: Int? = null,
) {
    init {
        require(command in 0..65535) { "command must be in 0..65535, was $command" }
        if (frame != null) require(frame in 0..255) { "frame must be in 0..255, was $frame" }
    }

    /** "MAV_CMD 400" or the name Pod knows for it, for messages. */
    public val label: String get() = CommandNames.of(command)

    override fun toString(): String = "$label(" +
        listOf(param1, param2, param3, param4, param5, param6, param7).joinToString() +
        (frame?.let { ", frame=$it" } ?: "") + ")"
}

/** Names for the MAV_CMD numbers Pod sends, for error messages and logs. */
internal object CommandNames {
    // Every `const val` of MavCommands is a static int field named as the command.
    private val names: Map<Int, String> = MavCommands::class.java.declaredFields
        .filter { it.type == Int::class.javaPrimitiveType }
        .associate { it.getInt(null) to it.name }

    fun of(command: Int): String = names[command]?.let { "MAV_CMD_$it" } ?: "MAV_CMD $command"
}
