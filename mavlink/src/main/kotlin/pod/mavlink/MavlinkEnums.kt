package pod.mavlink

import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType

/** Maps MAVLink enum numbers (MAV_TYPE, MAV_AUTOPILOT) to Pod's types and back. */
public object MavlinkEnums {
    internal const val MAV_TYPE_GCS = 6
    internal const val MAV_AUTOPILOT_INVALID = 8
    internal const val MAV_AUTOPILOT_GENERIC = 0
    internal const val MAV_AUTOPILOT_ARDUPILOTMEGA = 3
    internal const val MAV_AUTOPILOT_PX4 = 12

    /** MAV_TYPE numbers that are not vehicles even when an autopilot id is set. */
    private val notVehicles = setOf(
        MAV_TYPE_GCS, 18 /* onboard controller */, 26 /* gimbal */, 27 /* ADS-B */, 30 /* camera */,
        31 /* charging station */, 32 /* FLARM */, 33 /* servo */, 34 /* ODID */, 36 /* battery */,
        37 /* parachute */, 38 /* log */, 39 /* OSD */, 40 /* IMU */, 41 /* GPS */, 42 /* winch */,
    )

    /** True when a HEARTBEAT of MAV_TYPE [type] from MAV_AUTOPILOT [autopilot] comes from a vehicle (not a GCS, camera, gimbal…). */
    public fun isVehicle(type: Int, autopilot: Int): Boolean = autopilot != MAV_AUTOPILOT_INVALID && type !in notVehicles

    /** Pod's airframe kind for a MAV_TYPE number. */
    public fun vehicleType(type: Int): VehicleType = when (type) {
        2 -> VehicleType.QUADROTOR
        13 -> VehicleType.HEXAROTOR
        14 -> VehicleType.OCTOROTOR
        15 -> VehicleType.TRICOPTER
        4 -> VehicleType.HELICOPTER
        1 -> VehicleType.FIXED_WING
        19, 20, 21, 22, 23, 24, 25 -> VehicleType.VTOL
        10 -> VehicleType.GROUND_ROVER
        11 -> VehicleType.SURFACE_BOAT
        12 -> VehicleType.SUBMARINE
        else -> VehicleType.OTHER
    }

    /** The MAV_TYPE number for an airframe kind. */
    public fun mavType(type: VehicleType): Int = when (type) {
        VehicleType.QUADROTOR -> 2
        VehicleType.HEXAROTOR -> 13
        VehicleType.OCTOROTOR -> 14
        VehicleType.TRICOPTER -> 15
        VehicleType.HELICOPTER -> 4
        VehicleType.FIXED_WING -> 1
        VehicleType.VTOL -> 22
        VehicleType.GROUND_ROVER -> 10
        VehicleType.SURFACE_BOAT -> 11
        VehicleType.SUBMARINE -> 12
        VehicleType.OTHER -> 0
    }

    /** Pod's autopilot kind for a MAV_AUTOPILOT number. */
    public fun autopilot(autopilot: Int): Autopilot = when (autopilot) {
        // Wire numbers to Pod's kinds: a codec table; what each firmware does is in pod.mavlink.firmware.
        MAV_AUTOPILOT_ARDUPILOTMEGA -> Autopilot.ARDUPILOT
        MAV_AUTOPILOT_PX4 -> Autopilot.PX4
        MAV_AUTOPILOT_GENERIC -> Autopilot.GENERIC
        else -> Autopilot.OTHER
    }

    /** The MAV_AUTOPILOT number for an autopilot kind. */
    public fun mavAutopilot(autopilot: Autopilot): Int = when (autopilot) {
        Autopilot.ARDUPILOT -> MAV_AUTOPILOT_ARDUPILOTMEGA
        Autopilot.PX4 -> MAV_AUTOPILOT_PX4
        Autopilot.GENERIC, Autopilot.OTHER -> MAV_AUTOPILOT_GENERIC
    }
}
