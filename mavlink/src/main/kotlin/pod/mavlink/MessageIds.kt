package pod.mavlink

/**
 * The MAVLink message ids Pod names anywhere (stream rates it asks for, messages it requests, what
 * the simulator streams): one table for the ground station and the simulator. Numbers from the
 * common and minimal dialects (mavlink/message_definitions/v1.0/common.xml, minimal.xml).
 */
public object MessageIds {
    /** HEARTBEAT. */
    public const val HEARTBEAT: Int = 0

    /** SET_MODE (the legacy message; ArduPilot acknowledges it as "command 11"). */
    public const val SET_MODE: Int = 11

    /** SYS_STATUS: battery, sensors. */
    public const val SYS_STATUS: Int = 1

    /** GPS_RAW_INT: fix type and satellites. */
    public const val GPS_RAW_INT: Int = 24

    /** ATTITUDE. */
    public const val ATTITUDE: Int = 30

    /** GLOBAL_POSITION_INT: position, altitudes, velocity. */
    public const val GLOBAL_POSITION_INT: Int = 33

    /** MISSION_CURRENT: the item the vehicle flies. */
    public const val MISSION_CURRENT: Int = 42

    /** VFR_HUD: air and ground speed, heading, climb. */
    public const val VFR_HUD: Int = 74

    /** DISTANCE_SENSOR: a rangefinder's reading (a downward one measures the height above ground). */
    public const val DISTANCE_SENSOR: Int = 132

    /** AUTOPILOT_VERSION (sent when asked with MAV_CMD_REQUEST_MESSAGE, not streamed). */
    public const val AUTOPILOT_VERSION: Int = 148

    /** HOME_POSITION. */
    public const val HOME_POSITION: Int = 242

    /** EXTENDED_SYS_STATE: landed state. */
    public const val EXTENDED_SYS_STATE: Int = 245

    /** CAMERA_INFORMATION: a camera's identity and capabilities, sent when asked. */
    public const val CAMERA_INFORMATION: Int = 259
}
