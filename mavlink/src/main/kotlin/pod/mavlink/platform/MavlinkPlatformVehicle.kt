package pod.mavlink.platform

import kotlinx.coroutines.flow.StateFlow
import pod.core.platform.PlatformVehicle
import pod.core.units.Location
import pod.core.vehicle.Battery
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.LandedState
import pod.core.vehicle.Position
import pod.core.vehicle.VehicleType
import pod.mavlink.MavlinkVehicle

/** A [MavlinkVehicle] as the engine sees it: its system id, a name, its payloads and its telemetry. */
public class MavlinkPlatformVehicle internal constructor(
    /** The MAVLink vehicle underneath. */
    public val vehicle: MavlinkVehicle,
    /** What it carries: what the vehicle reported ([MavlinkVehicle.payloads]) unless the platform was told. */
    override val payloads: StateFlow<Set<String>>,
) : PlatformVehicle {
    override val id: Int get() = vehicle.systemId
    override val type: VehicleType get() = vehicle.identity.value.type
    override val name: String get() = "${kind(type)}-$id"
    override val connection: StateFlow<ConnectionState> get() = vehicle.connection
    override val position: StateFlow<Position?> get() = vehicle.telemetry.position
    override val battery: StateFlow<Battery?> get() = vehicle.telemetry.battery
    override val home: StateFlow<Location?> get() = vehicle.telemetry.home
    override val landedState: StateFlow<LandedState> get() = vehicle.telemetry.landedState

    override fun equals(other: Any?): Boolean = other is PlatformVehicle && other.id == id
    override fun hashCode(): Int = id
    override fun toString(): String = name

    private fun kind(type: VehicleType): String = when {
        type.isMultirotor -> "copter"
        type == VehicleType.FIXED_WING || type == VehicleType.VTOL -> "plane"
        type == VehicleType.GROUND_ROVER -> "rover"
        type == VehicleType.SURFACE_BOAT -> "boat"
        type == VehicleType.SUBMARINE -> "sub"
        else -> "vehicle"
    }
}
