package pod.mavlink.plan

import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleIdentity
import pod.core.vehicle.VehicleType
import pod.mavlink.firmware.Firmware

/**
 * The autopilot and airframe family a mission is written for: it decides how mission steps become
 * MAVLink items (item 0 as home on ArduPilot, an approach waypoint before a plane's landing, what
 * PX4 refuses) and how a vehicle is started on its mission. It is the mission-writing part of a
 * [pod.mavlink.firmware.Firmware]; the sources of each fact are in [MissionPlanner]'s KDoc.
 */
public enum class MissionFlavor(
    /** True when item 0 of the list is home and is not flown (ArduPilot). */
    public val homeAtZero: Boolean,
    /** True for fixed-wing airframes, which cannot hover. */
    public val fixedWing: Boolean,
    /** True when a change of altitude is flown as NAV_CONTINUE_AND_CHANGE_ALT (ArduPlane); elsewhere as a waypoint at the new height. */
    public val changesAltitudeByItem: Boolean = false,
    /** True when a climb or descent rate may be a DO_CHANGE_SPEED mission item (ArduCopter); elsewhere it is sent as a command. */
    public val climbRateByItem: Boolean = false,
    /** True when NAV_LOITER_TURNS is accepted; PX4 refuses it, and the turns become a timed loiter. */
    public val loitersByTurns: Boolean = true,
    /** True when a NaN yaw (param4) keeps the heading (PX4); ArduPilot stores 0 there. */
    public val nanYawKeepsHeading: Boolean = false,
    /** True when DO_LAND_START markers in the list are not steps of their own (ArduPlane's landing sequences). */
    public val landStartIsMarker: Boolean = false,
) {
    /** ArduPilot Copter (and other ArduPilot rotorcraft). */
    ARDUCOPTER(homeAtZero = true, fixedWing = false, climbRateByItem = true),

    /** ArduPilot Plane. */
    ARDUPLANE(homeAtZero = true, fixedWing = true, changesAltitudeByItem = true, landStartIsMarker = true),

    /** PX4 multicopter. */
    PX4(homeAtZero = false, fixedWing = false, loitersByTurns = false, nanYawKeepsHeading = true),

    /** PX4 fixed-wing. */
    PX4_FIXED_WING(homeAtZero = false, fixedWing = true, loitersByTurns = false, nanYawKeepsHeading = true),
    ;

    /** The first item a mission flies (1 on ArduPilot, where item 0 is home; 0 on PX4). */
    public val firstItem: Int get() = if (homeAtZero) 1 else 0

    /** True for PX4 flavours. */
    public val isPx4: Boolean get() = this == PX4 || this == PX4_FIXED_WING

    /** Finds the flavour a vehicle's missions take from what its heartbeat says. */
    public companion object {
        /** The flavour of a vehicle with [autopilot] flying [type]; generic autopilots are treated like PX4 (no home item). */
        public fun of(autopilot: Autopilot, type: VehicleType): MissionFlavor = Firmware.of(autopilot, type).missionFlavor

        /** The flavour of the vehicle [identity] describes. */
        public fun of(identity: VehicleIdentity): MissionFlavor = of(identity.autopilot, identity.type)
    }
}
