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

    /** Frames whose x and y are a latitude and a longitude. */
    public val GLOBAL_FRAMES: Set<Int> = setOf(GLOBAL, GLOBAL_RELATIVE_ALT, GLOBAL_INT, GLOBAL_RELATIVE_ALT_INT, GLOBAL_TERRAIN_ALT, GLOBAL_TERRAIN_ALT_INT)

    /**
     * Frames whose x and y are local positions in metres (sent × 10⁴ in integer messages): LOCAL_NED
     * 1, LOCAL_ENU 4, LOCAL_OFFSET_NED 7, BODY_NED 8, BODY_OFFSET_NED 9, BODY_FRD 12, the reserved
     * 13..19 (local frames once) and LOCAL_FRD 20, LOCAL_FLU 21.
     */
    public val LOCAL_FRAMES: Set<Int> = setOf(1, 4, 7, 8, 9, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21)

    /** True when a frame's x and y are a latitude and a longitude. */
    public fun isGlobal(frame: Int): Boolean = frame in GLOBAL_FRAMES
}
