package pod.core.platform

import kotlinx.coroutines.flow.StateFlow
import pod.core.units.Location
import pod.core.vehicle.Battery
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.LandedState
import pod.core.vehicle.Position
import pod.core.vehicle.VehicleType

/** A vehicle as the engine sees it: who it is and its live telemetry. Equal by [id]. */
public interface PlatformVehicle {
    /** Unique within the platform (the MAVLink system id). */
    public val id: Int

    /** A name for people: "copter-3". */
    public val name: String

    /** Airframe kind. */
    public val type: VehicleType

    /**
     * What it carries ("camera", …), for `pick { payload(…) }`: a flow, because a real vehicle
     * tells only after it is heard (a pick waiting for a camera is woken when one is reported).
     */
    public val payloads: StateFlow<Set<String>>

    /** Whether the vehicle is heard. */
    public val connection: StateFlow<ConnectionState>

    /** Where it is, or null before its first position report. */
    public val position: StateFlow<Position?>

    /** Battery state, or null before its first report. */
    public val battery: StateFlow<Battery?>

    /** Launch point, or null before the vehicle reports one. */
    public val home: StateFlow<Location?>

    /** On the ground, in the air, taking off or landing. */
    public val landedState: StateFlow<LandedState>
}
