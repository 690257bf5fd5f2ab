package pod.mavlink.vehicle

/** How a [MissionServer] behaves where ArduPilot and PX4 differ. */
public enum class MissionServerFlavor {
    /**
     * Requests items with the legacy MISSION_REQUEST, answers an unexpected item with a non-final
     * MISSION_ACK INVALID_SEQUENCE, re-requests after 1 s and gives up after 8 s with
     * OPERATION_CANCELLED, overwrites item 0 of a MISSION with home, answers a repeated last item
     * after completion with ERROR, supports MISSION_WRITE_PARTIAL_LIST, and stores items in its
     * own form ([pod.mavlink.mission.ArduPilotMissionStorage]).
     */
    ARDUPILOT,

    /**
     * Requests with MISSION_REQUEST_INT, ignores unexpected items, re-requests after 250 ms and
     * gives up silently after 5 s, keeps item 0, acknowledges a repeated last item again, ignores
     * partial writes, and serves downloads strictly in order (an out-of-turn request ends the
     * download with ERROR; 5 s without a request drop it silently).
     */
    PX4,
}
