package pod.mavlink.vehicle

import pod.mavlink.mission.ArduPilotMissionStorage
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionResult
import pod.mavlink.mission.MissionType

/** What a [MissionServer] refuses to store: the MISSION_ACK a real autopilot answers to an item it will not take. */
internal object StoredItemChecks {
    /** The MAV_MISSION_RESULT an autopilot of [flavor] would answer to [item], or null when it is acceptable. */
    fun problemWith(item: MissionItem, flavor: MissionServerFlavor): MissionResult? =
        (if (flavor == MissionServerFlavor.ARDUPILOT) ArduPilotMissionStorage.problem(item) else null) ?: commonProblemWith(item)

    private fun commonProblemWith(item: MissionItem): MissionResult? = when (item.missionType) {
        MissionType.MISSION -> when {
            item.frame !in MissionItem.GLOBAL_FRAMES && item.frame != MissionItem.FRAME_MISSION && item.frame !in MissionItem.LOCAL_FRAMES -> MissionResult.UNSUPPORTED_FRAME
            else -> coordinateProblem(item)
        }
        MissionType.FENCE -> when {
            item.command !in 5000..5004 -> MissionResult.UNSUPPORTED
            !item.isGlobal -> MissionResult.UNSUPPORTED_FRAME
            else -> coordinateProblem(item)
        }
        MissionType.RALLY -> when {
            item.command != 5100 -> MissionResult.UNSUPPORTED
            !item.isGlobal -> MissionResult.UNSUPPORTED_FRAME
            else -> coordinateProblem(item)
        }
    } ?: when {
        item.param1.isNaN() -> MissionResult.INVALID_PARAM1
        item.param2.isNaN() -> MissionResult.INVALID_PARAM2
        item.param3.isNaN() -> MissionResult.INVALID_PARAM3
        !item.z.isFinite() -> MissionResult.INVALID_PARAM7
        else -> null
    }

    private fun coordinateProblem(item: MissionItem): MissionResult? = when {
        !item.isGlobal -> null
        item.x !in -900_000_000..900_000_000 -> MissionResult.INVALID_PARAM5_X
        item.y !in -1_800_000_000..1_800_000_000 -> MissionResult.INVALID_PARAM6_Y
        else -> null
    }
}
