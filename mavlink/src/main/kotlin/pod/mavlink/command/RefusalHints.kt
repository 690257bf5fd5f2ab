package pod.mavlink.command

import pod.mavlink.firmware.Firmware
import pod.core.vehicle.VehicleIdentity

/**
 * What a person can do about a refusal the autopilot does not explain: a bare COMMAND_ACK FAILED
 * says nothing, but the vehicle's reported state often does.
 */
internal object RefusalHints {
    /** A hint for [command] refused with [result] by a vehicle in [mode], [armed] or not; null when there is none. */
    fun forRefusal(command: VehicleCommand, result: CommandResult?, identity: VehicleIdentity, mode: String?, armed: Boolean): String? {
        if (result == CommandResult.ACCEPTED || result == CommandResult.IN_PROGRESS) return null
        return when (command.command) {
            MavCommands.NAV_TAKEOFF -> when {
                !armed -> "vehicle ${identity.systemId} is disarmed: arm it first with `pod arm`"
                identity.type.isMultirotor && mode != null && Firmware.of(identity).takeOffCommandModes?.let { mode !in it } == true ->
                    "ArduCopter takes off on command only in GUIDED (or LOITER, POSHOLD), and vehicle ${identity.systemId} is in $mode: switch with `pod mode GUIDED`"
                else -> null
            }
            MavCommands.DO_PAUSE_CONTINUE -> pauseContinue(command.param1 == 0f, identity, mode)
            MavCommands.DO_REPOSITION -> if (!armed) "vehicle ${identity.systemId} is disarmed: arm it and take off first (`pod arm`, `pod takeoff ALT`)" else null
            // ArduPlane starts a landing sequence only in flight (a bare FAILED on the ground).
            MavCommands.DO_LAND_START -> if (!armed) "vehicle ${identity.systemId} is disarmed on the ground: there is nothing to land" else null
            else -> null
        }
    }

    /**
     * ArduCopter answers a pause or resume it cannot do with FAILED and only an INFO line
     * (GCS_MAVLINK_Copter::handle_command_pause_continue): only AUTO (a waypoint leg not yet
     * reached, ModeAuto::pause / ::resume) and GUIDED (ModeGuided::pause / ::resume) have them.
     */
    private fun pauseContinue(pause: Boolean, identity: VehicleIdentity, mode: String?): String? {
        if (!Firmware.of(identity).pausesGuidedFlight || !identity.type.isMultirotor) return null
        val id = identity.systemId
        return when {
            mode != "AUTO" && mode != "GUIDED" ->
                "ArduCopter ${if (pause) "pauses" else "resumes"} only in AUTO or GUIDED, and vehicle $id is in ${mode ?: "an unknown mode"}" +
                    if (pause) ": hold it with `pod mode BRAKE`" else ": continue the mission with `pod mode AUTO`"
            pause -> "vehicle $id is already paused, or not on a waypoint leg (ArduCopter pauses a leg only before it reaches the waypoint)"
            else -> "vehicle $id has nothing paused in $mode"
        }
    }
}
