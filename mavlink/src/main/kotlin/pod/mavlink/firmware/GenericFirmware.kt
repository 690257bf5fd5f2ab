package pod.mavlink.firmware

import pod.mavlink.plan.MissionFlavor
import pod.mavlink.telemetry.ModeRole

/**
 * A MAVLink autopilot Pod has no profile for (GENERIC, OTHER; MAVSDK's vehicle side among them).
 * Each fact is the fallback Pod used before profiles existed: ArduPilot's mode names, arming
 * modes and commands, PX4's mission storage (no home item, no take-off rule, no packed items)
 * and bytewise parameters.
 */
public data class GenericFirmware(
    /** True for a FIXED_WING or VTOL airframe. */
    override val fixedWing: Boolean,
) : Firmware() {
    private val modes: Firmware get() = if (fixedWing) ArduPlane else ArduCopter

    override val missionFlavor: MissionFlavor
        get() = if (fixedWing) MissionFlavor.PX4_FIXED_WING else MissionFlavor.PX4
    override val takeOffWay: TakeOffWay get() = modes.takeOffWay
    override val repositionTakesLoiterRadius: Boolean get() = fixedWing
    override val landsThroughLandingSequence: Boolean get() = fixedWing

    override fun armsIn(mode: String): Boolean = modes.armsIn(mode)

    override fun modeFor(role: ModeRole): String? = modes.modeFor(role)
}
