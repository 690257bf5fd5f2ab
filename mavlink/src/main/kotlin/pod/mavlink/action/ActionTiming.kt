package pod.mavlink.action

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** How long [VehicleActions] wait for what they asked to show, and for a vehicle still initialising. */
public data class ActionTiming(
    /** How long a state change (armed flag, mode) may take to show in telemetry after the ack. */
    public val confirmTimeout: Duration = 8.seconds,
    /**
     * How long [VehicleActions.arm] and [VehicleActions.setMode] wait for a vehicle that is still
     * initialising. Real autopilots take tens of seconds after boot: ArduCopter SITL arms ~43 s
     * after boot, ArduPlane ~23 s.
     */
    public val readyTimeout: Duration = 90.seconds,
) {
    init {
        require(confirmTimeout.isPositive()) { "confirmTimeout must be > 0, was $confirmTimeout" }
        require(!readyTimeout.isNegative()) { "readyTimeout must be ≥ 0, was $readyTimeout" }
    }
}
