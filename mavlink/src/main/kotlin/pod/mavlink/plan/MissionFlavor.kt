package pod.mavlink.plan

import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleIdentity
import pod.core.vehicle.VehicleType

/**
 * The autopilot and airframe family a mission is written for: it decides how mission steps become
 * MAVLink items (item 0 as home on ArduPilot, an approach waypoint before a plane's landing, what
 * PX4 refuses) and how a vehicle is started on its mission.
 */
public enum class MissionFlavor(
    /** True when item 0 of the list is home and is not flown (ArduPilot). */
    public val homeAtZero: Boolean,
    /** True for fixed-wing airframes, which cannot hover. */
    public val fixedWing: Boolean,
) {
    /** ArduPilot Copter (and other ArduPilot rotorcraft). */
    ARDUCOPTER(homeAtZero = true, fixedWing = false),

    /** ArduPilot Plane. */
    ARDUPLANE(homeAtZero = true, fixedWing = true),

    /** PX4 multicopter. */
    PX4(homeAtZero = false, fixedWing = false),

    /** PX4 fixed-wing. */
    PX4_FIXED_WING(homeAtZero = false, fixedWing = true),
    ;

    /** The first item a mission flies (1 on ArduPilot, where item 0 is home; 0 on PX4). */
    public val firstItem: Int get() = if (homeAtZero) 1 else 0

    /** True for PX4 flavours. */
    public val isPx4: Boolean get() = this == PX4 || this == PX4_FIXED_WING

    public companion object {
        /** The flavour of a vehicle with [autopilot] flying [type]; generic autopilots are treated like PX4 (no home item). */
        public fun of(autopilot: Autopilot, type: VehicleType): MissionFlavor {
            val plane = type == VehicleType.FIXED_WING || type == VehicleType.VTOL
            return when (autopilot) {
                Autopilot.ARDUPILOT -> if (plane) ARDUPLANE else ARDUCOPTER
                else -> if (plane) PX4_FIXED_WING else PX4
            }
        }

        /** The flavour of the vehicle [identity] describes. */
        public fun of(identity: VehicleIdentity): MissionFlavor = of(identity.autopilot, identity.type)
    }
}
