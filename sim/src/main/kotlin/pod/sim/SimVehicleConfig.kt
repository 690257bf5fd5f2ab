package pod.sim

import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.signing.SigningKey
import pod.sim.autopilot.profile.AutopilotProfile
import pod.sim.autopilot.profile.Px4Profile
import pod.sim.radio.SikRadio
import pod.sim.world.CameraFov
import pod.sim.world.Rangefinder
import pod.sim.world.SimObject
import pod.sim.world.Terrain
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * How a [SimVehicle] looks on the wire and how it behaves.
 *
 * [timeScale] speeds up the simulated world (flight, battery) relative to the wall clock, and the
 * messages it streams with it: at 40 a 1 Hz HEARTBEAT comes every 25 ms of wall time, as from
 * ArduPilot SITL run with a speed-up (no stream faster than 50 Hz of wall time; below 1, the
 * real-time rates).
 */
public data class SimVehicleConfig(
    /** MAVLink system id, 1..254. */
    public val systemId: Int,
    /** MAVLink component id of the autopilot. */
    public val componentId: Int = 1,
    /** Airframe it announces and flies as. */
    public val type: VehicleType = VehicleType.QUADROTOR,
    /** Autopilot: with [type], picks the firmware it plays (mode numbering, protocol quirks, behaviour). */
    public val autopilot: Autopilot = Autopilot.ARDUPILOT,
    /** Where it boots; altitude above mean sea level. */
    public val home: Location = DEFAULT_HOME,
    /** Where its telemetry goes, like SITL's `--out`: `udpout://127.0.0.1:14550`. */
    public val gcs: String = "udpout://127.0.0.1:14550",
    /** Initial battery charge, 0..1. */
    public val initialCharge: Double = 1.0,
    /** Simulated seconds per wall-clock second. */
    public val timeScale: Double = 1.0,
    /**
     * Message id → rate in Hz of simulated time of the streams it sends before anyone asks
     * (HEARTBEAT is always 1 Hz):
     * by default what the autopilot it plays sends on a fresh telemetry link ([defaultStreamRates]).
     */
    public val streamRates: Map<Int, Double> = defaultStreamRates(autopilot, type),
    /**
     * Simulated time after boot before the GPS has a 3D fix and the estimator sets its origin:
     * until then there is no home (no HOME_POSITION) and arming is refused ("Arm: AHRS: waiting
     * for home" on ArduPilot). Real ArduPilot SITL takes ~20 s; short here so tests stay fast.
     */
    public val positionReadyAfter: Duration = 2.seconds,
    /**
     * Simulated time after boot before the sensors pass the pre-arm checks: until then ArduPilot
     * refuses to arm with "Arm: Accels inconsistent" even with home set (real SITL: copter
     * armable ~43 s after boot, plane ~23 s). Defaults to [positionReadyAfter].
     */
    public val sensorsReadyAfter: Duration = positionReadyAfter,
    /**
     * Simulated time after boot before the estimator's position is good enough to navigate
     * (ArduCopter's position_ok): until then an ArduCopter refuses the modes that need a position
     * ("Mode change to GUIDED failed: requires position") while it may already arm in STABILIZE.
     * Real ArduCopter SITL shows such a window; defaults to [sensorsReadyAfter] (no window).
     */
    public val navigationReadyAfter: Duration = sensorsReadyAfter,
    /**
     * Parameter values it boots with instead of the defaults, as SITL's `--defaults` file:
     * `mapOf("DISARM_DELAY" to 0.0)`. Unknown names fail when the vehicle is created.
     */
    public val parameters: Map<String, Double> = emptyMap(),
    /**
     * Whether it carries a camera, and says so as ArduPilot 4.5+ does: CAMERA_INFORMATION when asked
     * with MAV_CMD_REQUEST_MESSAGE (refused without a camera), so `pick { payload("camera") }` finds it.
     */
    public val camera: Boolean = true,
    /** Simulated time the physics advances per integration step. */
    public val physicsStep: Duration = 50.milliseconds,
    /**
     * Simulated time after boot before the mission service takes uploads: until then an
     * ArduPilot-flavoured vehicle answers MISSION_COUNT with MAV_MISSION_NO_SPACE, as real
     * ArduPilot does while its mission storage is not yet initialised (a few seconds). Zero by
     * default so that tests which do not test this need not wait.
     */
    public val missionStorageReadyAfter: Duration = Duration.ZERO,
    /**
     * The ground it flies over; null (the default) is flat ground at [home]'s altitude. With a
     * terrain the vehicle boots standing on it: its home altitude is the terrain's elevation at
     * [home] ([home]'s own altitude is ignored), and it lands wherever the terrain is under it.
     * Give every vehicle of a scenario the same terrain so they share its hills.
     */
    public val terrain: Terrain? = null,
    /**
     * A downward lidar measuring the height above [terrain]; null (the default) is none. With one
     * the vehicle sends DISTANCE_SENSOR as its autopilot does: ArduPilot in its EXTRA3 stream group,
     * so only once a ground station asks (MAV_CMD_SET_MESSAGE_INTERVAL for message 132); PX4 at
     * 0.5 Hz unasked ([DEFAULT_STREAM_RATES]).
     */
    public val rangefinder: Rangefinder? = null,
    /** Objects on the ground that the camera's photos detect when they fall inside a photo's footprint. */
    public val objects: List<SimObject> = emptyList(),
    /** The camera's field of view, which with the height above the terrain sets a photo's footprint. */
    public val cameraFov: CameraFov = CameraFov.DEFAULT,
    /**
     * The MAVLink 2 signing key it boots with, as if set by SETUP_SIGNING earlier; null (the
     * default): unsigned until a ground station sends SETUP_SIGNING. Keyed, it signs what it sends
     * and ignores unsigned or forged frames but RADIO_STATUS and RADIO, as ArduPilot does
     * ([pod.sim.signing.ArduPilotSigning]).
     */
    public val signingKey: SigningKey? = null,
    /**
     * A SiK radio pair between the vehicle and its ground station, emulated at its serial rate with
     * bounded buffers ([pod.sim.radio.RadioLink]); null (the default) is a direct link.
     */
    public val radio: SikRadio? = null,
) {
    init {
        require(systemId in 1..254) { "systemId must be in 1..254, was $systemId" }
        require(componentId in 1..255) { "componentId must be in 1..255, was $componentId" }
        require(initialCharge in 0.0..1.0) { "initialCharge must be in 0..1, was $initialCharge" }
        require(timeScale > 0 && timeScale <= 1000) { "timeScale must be in (0, 1000], was $timeScale" }
        require(!positionReadyAfter.isNegative()) { "positionReadyAfter must not be negative, was $positionReadyAfter" }
        require(!sensorsReadyAfter.isNegative()) { "sensorsReadyAfter must not be negative, was $sensorsReadyAfter" }
        require(!navigationReadyAfter.isNegative()) { "navigationReadyAfter must not be negative, was $navigationReadyAfter" }
        require(!missionStorageReadyAfter.isNegative()) { "missionStorageReadyAfter must not be negative, was $missionStorageReadyAfter" }
        require(physicsStep > Duration.ZERO && physicsStep <= 1.seconds) { "physicsStep must be in (0, 1 s], was $physicsStep" }
        streamRates.forEach { (id, hz) -> require(hz >= 0 && hz <= 1000) { "stream rate for message $id must be in [0, 1000] Hz, was $hz" } }
        require(objects.map { it.id }.toSet().size == objects.size) { "objects must have distinct ids" }
    }

    /** Where it boots: [home], standing on the [terrain] when there is one. */
    internal val bootLocation: Location get() = terrain?.let { home.copy(altitude = it.elevationAt(home)) } ?: home

    /** Defaults of a simulated vehicle that depend on its autopilot and airframe. */
    public companion object {
        /** Near the Faculty of Engineering in Porto, where Dolphin was written. */
        public val DEFAULT_HOME: Location = Location(41.178_046, -8.595_786, 120.m)

        /**
         * What a vehicle of [autopilot] and [type] streams before a ground station asks, as its
         * autopilot profile says: ArduCopter nothing but HEARTBEAT (its SRn_ stream rates default
         * to 0), ArduPlane its stream groups at 1 Hz, PX4 [DEFAULT_STREAM_RATES] (its normal-mode set).
         */
        public fun defaultStreamRates(autopilot: Autopilot, type: VehicleType): Map<Int, Double> = AutopilotProfile.of(autopilot, type).streamDefaults

        /**
         * PX4's streams unasked: SYS_STATUS, GPS_RAW_INT, EXTENDED_SYS_STATE, MISSION_CURRENT 1 Hz;
         * GLOBAL_POSITION_INT, ATTITUDE, VFR_HUD 2 Hz; HOME_POSITION 0.2 Hz; DISTANCE_SENSOR 0.5 Hz
         * (PX4 src/modules/mavlink/mavlink_main.cpp, Mavlink::configure_streams_to_default,
         * MAVLINK_MODE_NORMAL).
         */
        public val DEFAULT_STREAM_RATES: Map<Int, Double> = Px4Profile.STREAM_DEFAULTS
    }
}
