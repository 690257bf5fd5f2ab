package pod.mavlink.telemetry

/**
 * How PX4 packs its flight mode into a HEARTBEAT's 32-bit custom_mode, and into DO_SET_MODE's
 * parameters: the main mode in bits 16..23, the sub-mode (of AUTO or POSCTL) in bits 24..31
 * (src/modules/commander/px4_custom_mode.h, union px4_custom_mode: reserved, main_mode, sub_mode).
 * The one place Pod writes this layout: [FlightModes] names what it unpacks, actions and the
 * simulator pack with it.
 */
public object Px4CustomMode {
    /** The custom_mode of main mode [main] and sub-mode [sub] (0: none). */
    public fun pack(main: Int, sub: Int = 0): Long = (main.toLong() shl MAIN_SHIFT) or (sub.toLong() shl SUB_SHIFT)

    /** The main mode in [customMode] (PX4_CUSTOM_MAIN_MODE_*: 4 AUTO, 3 POSCTL, …). */
    public fun main(customMode: Long): Int = ((customMode shr MAIN_SHIFT) and 0xFF).toInt()

    /** The sub-mode in [customMode] (PX4_CUSTOM_SUB_MODE_*; 0 when the main mode has none). */
    public fun sub(customMode: Long): Int = ((customMode shr SUB_SHIFT) and 0xFF).toInt()

    private const val MAIN_SHIFT = 16
    private const val SUB_SHIFT = 24
}
