package pod.core.vehicle

/** What kind of airframe or hull a vehicle is. */
public enum class VehicleType {
    /** Four-rotor multicopter. */
    QUADROTOR,
    /** Six-rotor multicopter. */
    HEXAROTOR,
    /** Eight-rotor multicopter. */
    OCTOROTOR,
    /** Three-rotor multicopter. */
    TRICOPTER,
    /** Single-rotor helicopter. */
    HELICOPTER,
    /** Fixed-wing aircraft. */
    FIXED_WING,
    /** Vertical take-off and landing hybrid. */
    VTOL,
    /** Ground rover. */
    GROUND_ROVER,
    /** Surface boat. */
    SURFACE_BOAT,
    /** Submarine. */
    SUBMARINE,
    /** Anything else. */
    OTHER,
    ;

    /** True for every rotorcraft that can hover. */
    public val isMultirotor: Boolean
        get() = this == QUADROTOR || this == HEXAROTOR || this == OCTOROTOR || this == TRICOPTER || this == HELICOPTER
}

/** Which autopilot firmware runs on the vehicle; it decides how modes are numbered. */
public enum class Autopilot {
    /** ArduPilot (Copter, Plane, Rover, Sub). */
    ARDUPILOT,
    /** PX4. */
    PX4,
    /** A generic MAVLink autopilot. */
    GENERIC,
    /** Anything else. */
    OTHER,
}

/** Who a vehicle is: its MAVLink address and what it announced in its heartbeat. */
public data class VehicleIdentity(
    /** MAVLink system id, 1..255. */
    public val systemId: Int,
    /** MAVLink component id of the autopilot (usually 1). */
    public val componentId: Int,
    /** Airframe kind. */
    public val type: VehicleType,
    /** Autopilot firmware. */
    public val autopilot: Autopilot,
)

/** A vehicle stopped sending heartbeats while something depended on it. */
public class VehicleLost(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** What was going on when it was lost. */
    public val during: String,
) : pod.core.PodException("vehicle $systemId was lost (no heartbeat) during $during")
