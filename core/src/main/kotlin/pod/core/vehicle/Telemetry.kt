package pod.core.vehicle

import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.Speed

/** Where a vehicle is and how it moves. */
public data class Position(
    /** Global position; its altitude is above mean sea level. */
    public val location: Location,
    /** Altitude above home. */
    public val relativeAltitude: Distance,
    /** Heading (0 = north, clockwise), or null when the vehicle does not know it. */
    public val heading: Angle?,
    /** Ground speed north. */
    public val velocityNorth: Speed,
    /** Ground speed east. */
    public val velocityEast: Speed,
    /** Vertical speed, positive down (MAVLink's convention). */
    public val velocityDown: Speed,
)

/** Battery state as the vehicle reports it. */
public data class Battery(
    /** Remaining charge as a fraction 0..1, or null when the vehicle does not estimate it. */
    public val remaining: Double?,
    /** Pack voltage in volts, or null when unknown. */
    public val voltage: Double?,
)

/**
 * The flight mode: the autopilot's own number and Pod's name for it ("AUTO", "GUIDED", "RTL", …,
 * or "MODE(n)" when the number is not one Pod knows for this autopilot and airframe).
 */
public data class FlightMode(
    /** Human-readable name. */
    public val name: String,
    /** The autopilot's custom_mode number. */
    public val customMode: Long,
)

/** Whether a vehicle is on the ground, in the air, or between the two. */
public enum class LandedState {
    /** The vehicle does not report it. */
    UNDEFINED,
    /** On the ground. */
    ON_GROUND,
    /** In the air. */
    IN_AIR,
    /** Taking off. */
    TAKEOFF,
    /** Landing. */
    LANDING,
}

/** GPS receiver state. */
public data class GpsStatus(
    /** Fix type as MAVLink's GPS_FIX_TYPE number (0 none … 3 3D, 4 DGPS, 5 RTK float, 6 RTK fixed), as sent. */
    public val fixType: Int,
    /** Satellites used, or null when unknown. */
    public val satellites: Int?,
) {
    /** [fixType] by name, or null for a number GPS_FIX_TYPE does not define (a receiver sending 255). */
    public val fix: GpsFix? get() = GpsFix.of(fixType)

    /** True for a 3D fix or better. */
    public val has3dFix: Boolean get() = fix?.let { it >= GpsFix.FIX_3D } ?: false
}

/** MAVLink's GPS_FIX_TYPE, in its order (the ordinal is the number on the wire). */
public enum class GpsFix {
    /** No GPS connected. */
    NO_GPS,
    /** No position information. */
    NO_FIX,
    /** 2D position. */
    FIX_2D,
    /** 3D position. */
    FIX_3D,
    /** DGPS/SBAS-aided 3D position. */
    DGPS,
    /** RTK float, 3D position. */
    RTK_FLOAT,
    /** RTK fixed, 3D position. */
    RTK_FIXED,
    /** Static fixed, typically a base station. */
    STATIC,
    /** PPP, 3D position. */
    PPP,
    ;

    /** Reads fix types as MAVLink numbers them. */
    public companion object {
        /** The fix type numbered [value], or null when GPS_FIX_TYPE has none. */
        public fun of(value: Int): GpsFix? = entries.getOrNull(value)
    }
}

/** How well a vehicle's messages reach us, counted from MAVLink sequence numbers. */
public data class LinkQuality(
    /** Frames received from the vehicle. */
    public val received: Long,
    /** Frames the vehicle sent that never arrived (gaps in its sequence numbers). */
    public val lost: Long,
) {
    /** Fraction of frames that arrived, 0..1 (1 when nothing was sent yet). */
    public val fraction: Double get() = if (received + lost == 0L) 1.0 else received.toDouble() / (received + lost)
}

/** Orientation of the vehicle body. */
public data class Attitude(
    /** Roll, right wing down positive. */
    public val roll: Angle,
    /** Pitch, nose up positive. */
    public val pitch: Angle,
    /** Yaw, clockwise from north. */
    public val yaw: Angle,
)

/** Whether Pod currently hears a vehicle. */
public enum class ConnectionState {
    /** Heartbeats arrive. */
    CONNECTED,
    /** No heartbeat for longer than the configured silence; the vehicle may come back. */
    LOST,
}

/** How serious a vehicle's text message is (MAV_SEVERITY, most serious first). */
public enum class Severity {
    /** System is unusable. */
    EMERGENCY,
    /** Action must be taken immediately. */
    ALERT,
    /** Critical condition; ArduPilot's arming-check failures come at this level. */
    CRITICAL,
    /** Error condition. */
    ERROR,
    /** Warning. */
    WARNING,
    /** Normal but significant. */
    NOTICE,
    /** Informational. */
    INFO,
    /** Debug output. */
    DEBUG,
}

/** A line of text a vehicle sent (STATUSTEXT): why it refused to arm, that it reached a waypoint, … */
public data class StatusText(
    /** How serious it is. */
    public val severity: Severity,
    /** What the autopilot said, in its words; a text it sent in several STATUSTEXT chunks arrives joined. */
    public val text: String,
)
