package pod.mavlink

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * How a [GroundStation] presents itself and tracks vehicles.
 *
 * @property streamRates message id → rate in Hz asked of every vehicle when it is found, with
 *   MAV_CMD_SET_MESSAGE_INTERVAL (ArduPilot streams nothing but HEARTBEAT until asked).
 */
public data class GroundStationConfig(
    /** Our MAVLink system id (255 is the usual ground station). */
    public val systemId: Int = 255,
    /** Our MAVLink component id (190 is MAV_COMP_ID_MISSIONPLANNER). */
    public val componentId: Int = 190,
    /** How often we send our own HEARTBEAT. */
    public val heartbeatInterval: Duration = 1.seconds,
    /** A vehicle silent (no HEARTBEAT) for longer than this is marked lost. */
    public val lostAfter: Duration = 3.seconds,
    /** MAVLink version of the frames we send: 2 (default) or 1. */
    public val mavlinkVersion: Int = 2,
    public val streamRates: Map<Int, Double> = DEFAULT_STREAM_RATES,
) {
    init {
        require(systemId in 1..255) { "systemId must be in 1..255, was $systemId" }
        require(componentId in 1..255) { "componentId must be in 1..255, was $componentId" }
        require(heartbeatInterval.isPositive()) { "heartbeatInterval must be > 0, was $heartbeatInterval" }
        require(lostAfter.isPositive()) { "lostAfter must be > 0, was $lostAfter" }
        require(mavlinkVersion == 1 || mavlinkVersion == 2) { "mavlinkVersion must be 1 or 2, was $mavlinkVersion" }
        streamRates.forEach { (id, hz) -> require(hz > 0 && hz <= 1000) { "stream rate for message $id must be in (0, 1000] Hz, was $hz" } }
    }

    public companion object {
        /** SYS_STATUS, GPS_RAW_INT and EXTENDED_SYS_STATE at 2 Hz; ATTITUDE and GLOBAL_POSITION_INT at 4 Hz; HOME_POSITION at 0.5 Hz. */
        public val DEFAULT_STREAM_RATES: Map<Int, Double> = mapOf(
            1 to 2.0, // SYS_STATUS
            24 to 2.0, // GPS_RAW_INT
            30 to 4.0, // ATTITUDE
            33 to 4.0, // GLOBAL_POSITION_INT
            242 to 0.5, // HOME_POSITION
            245 to 2.0, // EXTENDED_SYS_STATE
        )
    }
}
