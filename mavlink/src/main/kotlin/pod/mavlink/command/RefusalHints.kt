package pod.mavlink.command

import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleIdentity

/**
 * What a person can do about a refusal the autopilot does not explain: a bare COMMAND_ACK FAILED
 * says nothing, but the vehicle's reported state often does.
 */
internal object RefusalHints {
    /**
     * ArduCopter modes that take a takeoff command from a ground station: Mode::do_user_takeoff
     * (ArduCopter/mode.cpp) refuses unless the copter is armed, on the ground, and its mode's
     * has_user_takeoff(must_navigate) is true (ArduCopter/mode.h: GUIDED, LOITER, POSHOLD,
     * ZIGZAG; ALT_HOLD, SPORT and FLOWHOLD only when the pilot navigates, which NAV_TAKEOFF's
     * param3 = 0 rules out). GUIDED is the one that holds position with nobody on the sticks.
     */
    private val COPTER_TAKEOFF_MODES = setOf("GUIDED", "LOITER", "POSHOLD", "ZIGZAG")

    /** A hint for [command] refused with [result] by a vehicle in [mode], [armed] or not; null when there is none. */
    fun forRefusal(command: VehicleCommand, result: CommandResult?, identity: VehicleIdentity, mode: String?, armed: Boolean): String? {
        if (result == CommandResult.ACCEPTED || result == CommandResult.IN_PROGRESS) return null
        return when (command.command) {
            MavCommands.NAV_TAKEOFF -> when {
                !armed -> "vehicle ${identity.systemId} is disarmed: arm it first with `pod arm`"
                identity.autopilot == Autopilot.ARDUPILOT && identity.type.isMultirotor && mode != null && mode !in COPTER_TAKEOFF_MODES ->
                    "ArduCopter takes off on command only in GUIDED (or LOITER, POSHOLD), and vehicle ${identity.systemId} is in $mode: switch with `pod mode GUIDED`"
                else -> null
            }
            else -> null
        }
    }
}
