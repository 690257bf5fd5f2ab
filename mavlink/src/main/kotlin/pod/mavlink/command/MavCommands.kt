package pod.mavlink.command

/**
 * The MAV_CMD numbers Pod sends, serves or flies, named as in MAVLink's common dialect without the
 * `MAV_CMD_` prefix. One table for the ground station, the simulated autopilots and the tests.
 */
public object MavCommands {
    /** NAV_WAYPOINT. */
    public const val NAV_WAYPOINT: Int = 16
    /** NAV_LOITER_UNLIM. */
    public const val NAV_LOITER_UNLIM: Int = 17
    /** NAV_LOITER_TURNS. */
    public const val NAV_LOITER_TURNS: Int = 18
    /** NAV_LOITER_TIME. */
    public const val NAV_LOITER_TIME: Int = 19
    /** NAV_RETURN_TO_LAUNCH. */
    public const val NAV_RETURN_TO_LAUNCH: Int = 20
    /** NAV_LAND. */
    public const val NAV_LAND: Int = 21
    /** NAV_TAKEOFF. */
    public const val NAV_TAKEOFF: Int = 22
    /** NAV_CONTINUE_AND_CHANGE_ALT. */
    public const val NAV_CONTINUE_AND_CHANGE_ALT: Int = 30
    /** NAV_LOITER_TO_ALT. */
    public const val NAV_LOITER_TO_ALT: Int = 31
    /** DO_ORBIT: circle a point (param1 radius, negative counter-clockwise; param2 speed; x/y/z centre). */
    public const val DO_ORBIT: Int = 34
    /** NAV_SPLINE_WAYPOINT. */
    public const val NAV_SPLINE_WAYPOINT: Int = 82
    /** NAV_VTOL_TAKEOFF. */
    public const val NAV_VTOL_TAKEOFF: Int = 84
    /** NAV_VTOL_LAND. */
    public const val NAV_VTOL_LAND: Int = 85
    /** NAV_DELAY. */
    public const val NAV_DELAY: Int = 93
    /** CONDITION_DELAY. */
    public const val CONDITION_DELAY: Int = 112
    /** CONDITION_YAW. */
    public const val CONDITION_YAW: Int = 115
    /** DO_SET_MODE. */
    public const val DO_SET_MODE: Int = 176
    /** DO_JUMP. */
    public const val DO_JUMP: Int = 177
    /** DO_CHANGE_SPEED. */
    public const val DO_CHANGE_SPEED: Int = 178
    /** DO_SET_HOME. */
    public const val DO_SET_HOME: Int = 179
    /** DO_SET_SERVO. */
    public const val DO_SET_SERVO: Int = 183
    /** DO_LAND_START. */
    public const val DO_LAND_START: Int = 189
    /** DO_REPOSITION. */
    public const val DO_REPOSITION: Int = 192
    /** DO_PAUSE_CONTINUE. */
    public const val DO_PAUSE_CONTINUE: Int = 193
    /** DO_DIGICAM_CONTROL. */
    public const val DO_DIGICAM_CONTROL: Int = 203
    /** DO_SET_CAM_TRIGG_DIST. */
    public const val DO_SET_CAM_TRIGG_DIST: Int = 206
    /** DO_SET_MISSION_CURRENT. */
    public const val DO_SET_MISSION_CURRENT: Int = 224
    /** PREFLIGHT_CALIBRATION. */
    public const val PREFLIGHT_CALIBRATION: Int = 241
    /** MISSION_START. */
    public const val MISSION_START: Int = 300
    /** COMPONENT_ARM_DISARM. */
    public const val COMPONENT_ARM_DISARM: Int = 400
    /** SET_MESSAGE_INTERVAL. */
    public const val SET_MESSAGE_INTERVAL: Int = 511
    /** REQUEST_MESSAGE. */
    public const val REQUEST_MESSAGE: Int = 512
    /** IMAGE_START_CAPTURE. */
    public const val IMAGE_START_CAPTURE: Int = 2000
    /** IMAGE_STOP_CAPTURE. */
    public const val IMAGE_STOP_CAPTURE: Int = 2001

}

/** Special parameter values of some MAV_CMDs. */
public object MavCommandParams {
    /** param2 of COMPONENT_ARM_DISARM that skips the pre-arm checks (ArduPilot and PX4). */
    public const val ARM_FORCE_MAGIC: Int = 21196

    /** param1 flag of DO_SET_MODE: param2 (and on PX4 param3) carry the custom mode. */
    public const val MODE_FLAG_CUSTOM_MODE_ENABLED: Int = 1

    /** param2 flag of DO_REPOSITION (MAV_DO_REPOSITION_FLAGS_CHANGE_MODE): switch to guided first. */
    public const val REPOSITION_FLAG_CHANGE_MODE: Int = 1
}
