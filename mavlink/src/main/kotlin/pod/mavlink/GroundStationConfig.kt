package pod.mavlink

import kotlin.time.Duration
import pod.core.time.Timebase
import pod.mavlink.signing.LinkSigning
import pod.mavlink.radio.RadioPacing
import kotlin.time.TimeSource
import kotlin.time.Duration.Companion.seconds

/**
 * How a [GroundStation] presents itself and tracks vehicles.
 *
 * @property streamRates message id → rate in Hz asked of every vehicle when it is found (and found
 *   again), with MAV_CMD_SET_MESSAGE_INTERVAL: ArduCopter streams nothing but HEARTBEAT until asked.
 *   Asked again every [streamRequestInterval] while a message has not arrived, at most
 *   [streamRequestRounds] times.
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
    /** How long to wait for a requested stream (or the home) before asking again. */
    public val streamRequestInterval: Duration = 2.seconds,
    /** How many times a stream that does not come is asked for. */
    public val streamRequestRounds: Int = 5,
    /**
     * Ask each vehicle found for HOME_POSITION at once (MAV_CMD_REQUEST_MESSAGE), and again every
     * [streamRequestInterval] until it has one: real autopilots have no home until their estimator
     * sets an origin, tens of seconds after boot.
     */
    public val requestHome: Boolean = true,
    /**
     * Ask each vehicle found, once, for CAMERA_INFORMATION (MAV_CMD_REQUEST_MESSAGE): a vehicle
     * with a camera answers and then carries "camera" ([MavlinkVehicle.payloads]).
     */
    public val requestPayloads: Boolean = true,
    /**
     * Most source addresses the station keeps a frame decoder for; beyond it the one heard least
     * recently is dropped (counted in [LinkStats.evictedPeers]), so a flood of datagrams from
     * spoofed addresses cannot grow memory without limit.
     */
    public val maxPeers: Int = 1024,
    /**
     * The clock every time reading of the station and its vehicles' protocols goes through
     * (heartbeat silence, exchange and readiness deadlines) and the dispatcher its coroutines run
     * on, whose delays follow that clock; a test passes a virtual one.
     */
    public val timebase: Timebase = Timebase.System,
    /**
     * How often, on [timebase]'s dispatcher, vehicles' silence is checked against [lostAfter];
     * null: a quarter of [lostAfter], at most 250 ms. A replay whose clock is the log's own checks
     * more often, so that a gap of a few seconds of log at a high speed is not missed.
     */
    public val silenceCheckEvery: Duration? = null,
    /**
     * Timeouts and retries of the commands, parameter exchanges, mission transfers and actions of
     * every vehicle found, fixed when it is found.
     */
    public val vehicleTiming: VehicleTiming = VehicleTiming(),
    /** MAVLink 2 signing on this link ([LinkSigning]); null (the default): frames unsigned, nothing verified. */
    public val signing: LinkSigning? = null,
    /** How sends are paced once a telemetry radio reports RADIO_STATUS; [RadioPacing.Off] never paces. */
    public val radioPacing: RadioPacing = RadioPacing(),
) {
    init {
        require(systemId in 1..255) { "systemId must be in 1..255, was $systemId" }
        require(componentId in 1..255) { "componentId must be in 1..255, was $componentId" }
        require(heartbeatInterval.isPositive()) { "heartbeatInterval must be > 0, was $heartbeatInterval" }
        require(lostAfter.isPositive()) { "lostAfter must be > 0, was $lostAfter" }
        require(mavlinkVersion == 1 || mavlinkVersion == 2) { "mavlinkVersion must be 1 or 2, was $mavlinkVersion" }
        require(streamRequestInterval.isPositive()) { "streamRequestInterval must be > 0, was $streamRequestInterval" }
        require(streamRequestRounds >= 1) { "streamRequestRounds must be ≥ 1, was $streamRequestRounds" }
        require(signing == null || mavlinkVersion == 2) { "signing needs mavlinkVersion 2: MAVLink 1 frames cannot be signed" }
        require(maxPeers >= 1) { "maxPeers must be ≥ 1, was $maxPeers" }
        require(silenceCheckEvery == null || silenceCheckEvery.isPositive()) { "silenceCheckEvery must be > 0, was $silenceCheckEvery" }
        streamRates.forEach { (id, hz) -> require(hz > 0 && hz <= 1000) { "stream rate for message $id must be in (0, 1000] Hz, was $hz" } }
    }

    /** [timebase]'s clock. */
    public val clock: TimeSource get() = timebase.clock

    /** The defaults a ground station's configuration starts from. */
    public companion object {
        /**
         * What a mission executor needs: SYS_STATUS, GPS_RAW_INT, MISSION_CURRENT and
         * EXTENDED_SYS_STATE at 2 Hz; ATTITUDE and GLOBAL_POSITION_INT at 4 Hz; HOME_POSITION at
         * 0.2 Hz (it is also asked for at once, see [requestHome]). MISSION_CURRENT is the only
         * report of progress through items that ArduCopter never reports reached (a final NAV_LAND).
         */
        public val DEFAULT_STREAM_RATES: Map<Int, Double> = mapOf(
            MessageIds.SYS_STATUS to 2.0,
            MessageIds.GPS_RAW_INT to 2.0,
            MessageIds.ATTITUDE to 4.0,
            MessageIds.GLOBAL_POSITION_INT to 4.0,
            MessageIds.MISSION_CURRENT to 2.0,
            MessageIds.HOME_POSITION to 0.2,
            MessageIds.EXTENDED_SYS_STATE to 2.0,
        )
    }
}
