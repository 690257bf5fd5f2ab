package pod.mavlink.mission

import pod.mavlink.MavFrames

/** Which of a vehicle's three lists a transfer concerns (MAV_MISSION_TYPE). */
public enum class MissionType(
    /** The MAV_MISSION_TYPE number on the wire. */
    public val mavValue: Int,
) {
    /** The flight plan. */
    MISSION(0),

    /** Geofence definitions. */
    FENCE(1),

    /** Rally (safe) points. */
    RALLY(2),
    ;

    /** Reads mission types as MAVLink numbers them (MAV_MISSION_TYPE). */
    public companion object {
        /** The type with MAV_MISSION_TYPE number [value], or null (255 = ALL is not a list). */
        public fun of(value: Int): MissionType? = entries.firstOrNull { it.mavValue == value }
    }
}

/**
 * One item of a mission, fence or rally list, exactly as MISSION_ITEM_INT carries it.
 *
 * [x] and [y] are the wire integers: degrees × 10⁷ in global frames, metres × 10⁴ in local frames,
 * plain integer parameters in MAV_FRAME_MISSION; [latitude]/[longitude] convert for global frames.
 */
public data class MissionItem(
    /** Position in the list, from 0. */
    public val seq: Int,
    /** MAV_FRAME number (0 global MSL, 3 global relative altitude, 2 mission, 10 terrain, …). */
    public val frame: Int,
    /** MAV_CMD number (16 NAV_WAYPOINT, 22 NAV_TAKEOFF, …). */
    public val command: Int,
    /** True for the item the vehicle should execute first. */
    public val current: Boolean = false,
    /** Continue to the next item when this one completes. */
    public val autocontinue: Boolean = true,
    /** PARAM1 of the command. */
    public val param1: Float = 0f,
    /** PARAM2 of the command. */
    public val param2: Float = 0f,
    /** PARAM3 of the command. */
    public val param3: Float = 0f,
    /** PARAM4 of the command (often yaw; NaN means "unchanged" for many commands). */
    public val param4: Float = 0f,
    /** PARAM5 / latitude as on the wire (see the class comment). */
    public val x: Int = 0,
    /** PARAM6 / longitude as on the wire. */
    public val y: Int = 0,
    /** PARAM7 / altitude in metres (its reference depends on [frame]). */
    public val z: Float = 0f,
    /** The list this item belongs to. */
    public val missionType: MissionType = MissionType.MISSION,
) {
    /** Latitude in degrees, for items in a global frame. */
    public val latitude: Double get() = x / 1e7

    /** Longitude in degrees, for items in a global frame. */
    public val longitude: Double get() = y / 1e7

    /** True when [x] and [y] are a latitude and longitude (MAV_FRAME_GLOBAL* and terrain frames). */
    public val isGlobal: Boolean get() = MavFrames.isGlobal(frame)

    /** The MAV_FRAME numbers that decide how an item's x, y and z are read. */
    public companion object {
        /** MAV_FRAME numbers whose x/y are latitude/longitude. */
        public val GLOBAL_FRAMES: Set<Int> = MavFrames.GLOBAL_FRAMES

        /** MAV_FRAME numbers whose x/y are local positions in metres (sent × 10⁴). */
        public val LOCAL_FRAMES: Set<Int> = MavFrames.LOCAL_FRAMES

        /** MAV_FRAME_MISSION: x/y are plain parameters. */
        public const val FRAME_MISSION: Int = MavFrames.MISSION
    }
}
