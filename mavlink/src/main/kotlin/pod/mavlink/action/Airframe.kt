package pod.mavlink.action

import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.MavlinkVehicle
import pod.mavlink.firmware.Firmware
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.telemetry.ModeRole

/** The vehicle's autopilot and airframe, as its latest HEARTBEAT said: what every action's choices depend on. */
internal fun MavlinkVehicle.airframe(): Pair<Autopilot, VehicleType> = identity.value.let { it.autopilot to it.type }

/** What the vehicle's firmware does differently, from its latest HEARTBEAT. */
internal fun MavlinkVehicle.firmware(): Firmware = Firmware.of(identity.value)

/** True for airframes that fly as a plane (a VTOL too): they circle to hold and land through a mission. */
internal val VehicleType.isPlane: Boolean get() = this == VehicleType.FIXED_WING || this == VehicleType.VTOL

/** The name of the mode that plays [role] on this vehicle; [ActionUnsupported] when it has none. */
internal fun MavlinkVehicle.modeFor(role: ModeRole): String {
    val (autopilot, type) = airframe()
    return FlightModes.forRole(autopilot, type, role)
        ?: throw ActionUnsupported(role.name.lowercase(), "$autopilot ${type.name.lowercase()} has no mode for it")
}
