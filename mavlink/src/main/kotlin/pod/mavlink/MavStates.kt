package pod.mavlink

/**
 * MAV_STATE numbers, a HEARTBEAT's `system_status` (common.xml, enum MAV_STATE): the one table Pod
 * reads them from ([pod.mavlink.telemetry.VehicleTelemetry.systemStatus]).
 */
public object MavStates {
    /** Uninitialised: state unknown. */
    public const val UNINIT: Int = 0

    /** Booting up. */
    public const val BOOT: Int = 1

    /** Calibrating: not flight-ready. */
    public const val CALIBRATING: Int = 2

    /** On the ground, ready to arm (ArduCopter says so even while its estimator initialises). */
    public const val STANDBY: Int = 3

    /** Motors armed: active. */
    public const val ACTIVE: Int = 4

    /** A non-normal flight mode: it can still navigate. */
    public const val CRITICAL: Int = 5

    /** Lost control of parts or all of the system: mayday. */
    public const val EMERGENCY: Int = 6

    /** Powering down. */
    public const val POWEROFF: Int = 7

    /** Terminating the flight. */
    public const val FLIGHT_TERMINATION: Int = 8

    /** True for the states a vehicle reports before it is ready: uninitialised, booting, calibrating. */
    public fun isStartingUp(state: Int): Boolean = state == UNINIT || state == BOOT || state == CALIBRATING
}
