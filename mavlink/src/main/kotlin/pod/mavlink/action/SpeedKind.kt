package pod.mavlink.action

/** Which speed MAV_CMD_DO_CHANGE_SPEED sets (its param1). */
public enum class SpeedKind(
    /** The number on the wire. */
    public val mavValue: Int,
) {
    /** Airspeed. */
    AIR(0),
    /** Ground speed. */
    GROUND(1),
    /** Climb rate. */
    CLIMB(2),
    /** Descent rate. */
    DESCENT(3),
}
