package pod.mavlink.mission

/** MAV_MISSION_RESULT: how a vehicle answered a mission transfer. */
public enum class MissionResult(
    /** The number on the wire. */
    public val mavValue: Int,
) {
    /** Mission accepted OK. */
    ACCEPTED(0),

    /** Generic error / not accepting mission commands at all right now. */
    ERROR(1),

    /** Coordinate frame is not supported. */
    UNSUPPORTED_FRAME(2),

    /** Command is not supported. */
    UNSUPPORTED(3),

    /** Mission items exceed storage space. */
    NO_SPACE(4),

    /** One of the parameters has an invalid value. */
    INVALID(5),

    /** param1 has an invalid value. */
    INVALID_PARAM1(6),

    /** param2 has an invalid value. */
    INVALID_PARAM2(7),

    /** param3 has an invalid value. */
    INVALID_PARAM3(8),

    /** param4 has an invalid value. */
    INVALID_PARAM4(9),

    /** x / param5 has an invalid value. */
    INVALID_PARAM5_X(10),

    /** y / param6 has an invalid value. */
    INVALID_PARAM6_Y(11),

    /** z / param7 has an invalid value. */
    INVALID_PARAM7(12),

    /** Mission item received out of sequence. */
    INVALID_SEQUENCE(13),

    /** Not accepting any mission commands from this communication partner. */
    DENIED(14),

    /** Current mission operation cancelled (e.g. mission upload, mission download). */
    OPERATION_CANCELLED(15),
    ;

    /** Reads results as MAVLink numbers them (MAV_MISSION_RESULT). */
    public companion object {
        /** The result with number [value], or null for a number this dialect does not define. */
        public fun of(value: Int): MissionResult? = entries.firstOrNull { it.mavValue == value }
    }
}
