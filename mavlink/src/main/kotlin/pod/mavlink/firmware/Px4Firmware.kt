package pod.mavlink.firmware

import pod.mavlink.plan.MissionFlavor
import pod.mavlink.telemetry.ModeRole

/** What PX4 does the same on every airframe; [Px4Multicopter] and [Px4FixedWing] add the airframe. */
public sealed class Px4Firmware : Firmware() {
    // Return, Land, Precision land and Orbit (src/modules/commander/ModeUtil/mode_requirements.cpp,
    // `mode_req_prevent_arming`).
    private val notArmable = setOf("AUTO.RTL", "AUTO.LAND", "AUTO.PRECLAND", "POSCTL.ORBIT")

    override val takeOffWay: TakeOffWay get() = TakeOffWay.COMMAND_ANYWHERE
    override val servesMissionInOrder: Boolean get() = true
    override val missionStartArms: Boolean get() = true
    override val repositionSwitchesMode: Boolean get() = true
    override val orbitsOnCommand: Boolean get() = true
    override val numbersEveryStatusText: Boolean get() = true
    override val loiterRadiusParam: String get() = "NAV_LOITER_RAD"
    override val hoverSpeedParam: String get() = "MPC_XY_CRUISE"
    override val hoverSpeedPerMetre: Double get() = 1.0
    override val cruiseSpeedParam: String get() = "FW_AIRSPD_TRIM"

    override fun armsIn(mode: String): Boolean = mode !in notArmable

    override fun modeFor(role: ModeRole): String = when (role) {
        // Hold (AUTO.LOITER) loiters where it is at its current altitude, no stick input used
        // (PX4 src/modules/navigator/loiter.cpp Loiter::on_activation -> set_loiter_position:
        // a loiter item from the current position, braking first on a multicopter).
        ModeRole.HOLD, ModeRole.GUIDED -> "AUTO.LOITER"
        ModeRole.MISSION -> "AUTO.MISSION"
        ModeRole.RETURN -> "AUTO.RTL"
        ModeRole.LAND -> "AUTO.LAND"
        ModeRole.TAKEOFF -> "AUTO.TAKEOFF"
    }
}

/** PX4 multicopter. */
public data object Px4Multicopter : Px4Firmware() {
    override val missionFlavor: MissionFlavor get() = MissionFlavor.PX4
    override val fixedWing: Boolean get() = false
}

/** PX4 fixed-wing. */
public data object Px4FixedWing : Px4Firmware() {
    override val missionFlavor: MissionFlavor get() = MissionFlavor.PX4_FIXED_WING
    override val fixedWing: Boolean get() = true
}
