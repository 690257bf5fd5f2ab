package pod.mavlink.mission

/** Compares what a vehicle holds with what was sent to it, in the form the vehicle keeps items. */
internal object MissionStorage {

    /**
     * True when [onBoard] is what a vehicle keeps after being sent [sent]. An ArduPilot vehicle
     * keeps its own packed form ([ArduPilotMissionStorage]; [fixedWing] for ArduPlane) and its home
     * in item 0 of a mission ([homeFirst]: the list starts at item 0), so both sides are compared
     * in that form; for other vehicles the items must match field for field (the current flag aside).
     */
    fun holds(
        type: MissionType,
        onBoard: List<MissionItem>,
        sent: List<MissionItem>,
        ardupilot: Boolean,
        fixedWing: Boolean,
        homeFirst: Boolean = true,
    ): Boolean {
        if (onBoard.size != sent.size) return false
        val skip = if (ardupilot && homeFirst && type == MissionType.MISSION) 1 else 0
        if (!ardupilot) return onBoard.map { it.copy(current = false) } == sent.map { it.copy(current = false) }
        return onBoard.drop(skip).zip(sent.drop(skip)).all { (held, given) ->
            sameStored(ArduPilotMissionStorage.stored(held, fixedWing), ArduPilotMissionStorage.stored(given, fixedWing))
        }
    }

    /**
     * Both in ArduPilot's form, equal up to what storing twice may change: a -0 that comes back 0
     * (ArduPilot sends a counter-clockwise radius of 0 as -0), an altitude a centimetre off
     * (centimetres in storage, metres as float on the wire).
     */
    private fun sameStored(a: MissionItem, b: MissionItem): Boolean =
        a.copy(param1 = a.param1 + 0f, param2 = a.param2 + 0f, param3 = a.param3 + 0f, param4 = a.param4 + 0f, z = 0f) ==
            b.copy(param1 = b.param1 + 0f, param2 = b.param2 + 0f, param3 = b.param3 + 0f, param4 = b.param4 + 0f, z = 0f) &&
            kotlin.math.abs(a.z - b.z) <= ALTITUDE_TOLERANCE_M

    private const val ALTITUDE_TOLERANCE_M = 0.011f
}
