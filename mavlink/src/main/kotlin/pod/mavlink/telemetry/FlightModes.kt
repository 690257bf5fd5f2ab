package pod.mavlink.telemetry

import pod.core.vehicle.Autopilot
import pod.core.vehicle.FlightMode
import pod.core.vehicle.VehicleType
import pod.mavlink.firmware.Firmware

/**
 * Names of autopilot flight modes, from the custom_mode number a HEARTBEAT carries and back.
 *
 * ArduPilot numbers modes per vehicle family (Copter and Plane tables here); PX4 packs a main mode
 * and a sub-mode of AUTO or POSCTL into one number ([Px4CustomMode]), named "MAIN.SUB" here
 * ("AUTO.LOITER", "POSCTL.ORBIT").
 */
public object FlightModes {
    private val arduCopter = mapOf(
        0 to "STABILIZE", 1 to "ACRO", 2 to "ALT_HOLD", 3 to "AUTO", 4 to "GUIDED", 5 to "LOITER",
        6 to "RTL", 7 to "CIRCLE", 9 to "LAND", 11 to "DRIFT", 13 to "SPORT", 14 to "FLIP",
        15 to "AUTOTUNE", 16 to "POSHOLD", 17 to "BRAKE", 18 to "THROW", 19 to "AVOID_ADSB",
        20 to "GUIDED_NOGPS", 21 to "SMART_RTL", 22 to "FLOWHOLD", 23 to "FOLLOW", 24 to "ZIGZAG",
        25 to "SYSTEMID", 26 to "AUTOROTATE", 27 to "AUTO_RTL",
    )
    private val arduPlane = mapOf(
        0 to "MANUAL", 1 to "CIRCLE", 2 to "STABILIZE", 3 to "TRAINING", 4 to "ACRO", 5 to "FBWA",
        6 to "FBWB", 7 to "CRUISE", 8 to "AUTOTUNE", 10 to "AUTO", 11 to "RTL", 12 to "LOITER",
        13 to "TAKEOFF", 14 to "AVOID_ADSB", 15 to "GUIDED", 17 to "QSTABILIZE", 18 to "QHOVER",
        19 to "QLOITER", 20 to "QLAND", 21 to "QRTL", 22 to "QAUTOTUNE", 23 to "QACRO", 24 to "THERMAL",
        25 to "LOITER_ALT_QLAND",
    )
    private val px4Main = mapOf(
        1 to "MANUAL", 2 to "ALTCTL", 3 to "POSCTL", 4 to "AUTO", 5 to "ACRO", 6 to "OFFBOARD",
        7 to "STABILIZED", 8 to "RATTITUDE",
    )
    private val px4AutoSub = mapOf(
        1 to "READY", 2 to "TAKEOFF", 3 to "LOITER", 4 to "MISSION", 5 to "RTL", 6 to "LAND",
        8 to "FOLLOW_TARGET", 9 to "PRECLAND", 10 to "VTOL_TAKEOFF",
    )

    // PX4's orbit (NAVIGATION_STATE_ORBIT, a multicopter circling after DO_ORBIT) is reported as
    // main mode POSCTL with sub mode PX4_CUSTOM_SUB_MODE_POSCTL_ORBIT = 1
    // (src/modules/commander/px4_custom_mode.h; get_mavlink_mode_state in commander_helper /
    // mavlink_messages sets both for NAVIGATION_STATE_ORBIT). Sub mode 0 is plain POSCTL.
    private val px4PosctlSub = mapOf(1 to "ORBIT")

    /** The mode [customMode] means on [autopilot] flying a [type] airframe. */
    public fun decode(autopilot: Autopilot, type: VehicleType, customMode: Long): FlightMode =
        FlightMode(nameOf(autopilot, type, customMode) ?: "MODE($customMode)", customMode)

    /**
     * The custom_mode number of the mode called [name] on [autopilot] flying [type], or null when
     * that autopilot has no such mode.
     */
    public fun customMode(autopilot: Autopilot, type: VehicleType, name: String): Long? = when (autopilot) {
        // Numbering, not behaviour: how each firmware encodes custom_mode is this codec's concern.
        Autopilot.PX4 -> {
            val parts = name.uppercase().split('.')
            val main = px4Main.entries.firstOrNull { it.value == parts[0] }?.key
            val sub = parts.getOrNull(1)?.let { s -> px4SubModes(main).entries.firstOrNull { it.value == s }?.key }
            when {
                main == null -> null
                parts.size == 1 -> Px4CustomMode.pack(main)
                sub == null || parts.size > 2 -> null
                else -> Px4CustomMode.pack(main, sub)
            }
        }
        else -> arduTable(type).entries.firstOrNull { it.value == name.uppercase() }?.key?.toLong()
    }

    /**
     * The name of the mode that plays [role] on [autopilot] flying [type], or null when it has none
     * (an ArduPilot plane has no LAND mode: it lands through its mission's landing sequence).
     *
     * [ModeRole.HOLD] is a mode that keeps position and altitude with nobody on the sticks, since
     * a vehicle Pod flies may have no transmitter (or one with its throttle at minimum).
     */
    public fun forRole(autopilot: Autopilot, type: VehicleType, role: ModeRole): String? =
        Firmware.of(autopilot, type).modeFor(role)

    /** Every mode name Pod knows for [autopilot] flying [type]. */
    public fun names(autopilot: Autopilot, type: VehicleType): List<String> = when (autopilot) {
        // The mode tables are numbering, kept beside their codec rather than in [Firmware].
        Autopilot.PX4 -> px4Main.values.filter { it != "AUTO" } + px4AutoSub.values.map { "AUTO.$it" } + px4PosctlSub.values.map { "POSCTL.$it" }
        else -> arduTable(type).values.toList()
    }

    private fun nameOf(autopilot: Autopilot, type: VehicleType, customMode: Long): String? = when (autopilot) {
        // Numbering, not behaviour: the inverse of [customMode].
        Autopilot.PX4 -> {
            val main = Px4CustomMode.main(customMode)
            val sub = Px4CustomMode.sub(customMode)
            val mainName = px4Main[main]
            when {
                mainName == null -> null
                else -> px4SubModes(main)[sub]?.let { "$mainName.$it" } ?: mainName
            }
        }
        Autopilot.ARDUPILOT -> arduTable(type)[customMode.toInt()]
        else -> null
    }

    private fun px4SubModes(main: Int?): Map<Int, String> = when (main) {
        PX4_AUTO -> px4AutoSub
        PX4_POSCTL -> px4PosctlSub
        else -> emptyMap()
    }

    private fun arduTable(type: VehicleType): Map<Int, String> = if (type.isFixedWing) arduPlane else arduCopter

    private val VehicleType.isFixedWing: Boolean get() = this == VehicleType.FIXED_WING || this == VehicleType.VTOL

    private const val PX4_AUTO = 4
    private const val PX4_POSCTL = 3
}

/** What a flight mode is for, so actions can pick the right mode on every autopilot. */
public enum class ModeRole {
    /** Stay where it is: hover, or circle for a plane. */
    HOLD,
    /** Fly to points the ground station gives. */
    GUIDED,
    /** Fly the uploaded mission. */
    MISSION,
    /** Return to launch. */
    RETURN,
    /** Land where it is. */
    LAND,
    /** Take off. */
    TAKEOFF,
}
