package pod.mavlink

import kotlin.time.Duration

/** Something that happened to the fleet a [GroundStation] tracks. */
public sealed class FleetEvent {
    /** The vehicle concerned. */
    public abstract val vehicle: MavlinkVehicle

    /** A vehicle was heard for the first time. */
    public data class Found(override val vehicle: MavlinkVehicle) : FleetEvent()

    /**
     * A vehicle has been silent for [silence], longer than the configured limit.
     *
     * @property silence how long nothing has been heard from it when it is declared lost.
     */
    public data class Lost(override val vehicle: MavlinkVehicle, val silence: Duration) : FleetEvent()

    /** A lost vehicle is heard again. */
    public data class Regained(override val vehicle: MavlinkVehicle) : FleetEvent()
}
