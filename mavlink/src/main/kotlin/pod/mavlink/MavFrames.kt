package pod.mavlink

/**
 * MAV_FRAME numbers Pod uses (common.xml, enum MAV_FRAME): one table for commands, mission items
 * and the simulator.
 */
public object MavFrames {
    /** Latitude, longitude, altitude above mean sea level (mission items: degrees as floats). */
    public const val GLOBAL: Int = 0

    /** x, y, z are plain parameters, not a position. */
    public const val MISSION: Int = 2

    /** Latitude, longitude, altitude above home. */
    public const val GLOBAL_RELATIVE_ALT: Int = 3

    /** [GLOBAL] with latitude and longitude as degrees × 10⁷ (COMMAND_INT, deprecated for items). */
    public const val GLOBAL_INT: Int = 5

    /** [GLOBAL_RELATIVE_ALT] with latitude and longitude as degrees × 10⁷. */
    public const val GLOBAL_RELATIVE_ALT_INT: Int = 6

    /** Latitude, longitude, altitude above the terrain. */
    public const val GLOBAL_TERRAIN_ALT: Int = 10

    /** [GLOBAL_TERRAIN_ALT] with latitude and longitude as degrees × 10⁷. */
    public const val GLOBAL_TERRAIN_ALT_INT: Int = 11

    /** True when a frame's x and y are a latitude and a longitude. */
    public fun isGlobal(frame: Int): Boolean =
        frame == GLOBAL || frame == GLOBAL_RELATIVE_ALT || frame == GLOBAL_INT || frame == GLOBAL_RELATIVE_ALT_INT ||
            frame == GLOBAL_TERRAIN_ALT || frame == GLOBAL_TERRAIN_ALT_INT
}
