package pod.mavlink.telemetry

import io.dronefleet.mavlink.common.Attitude as AttitudeMessage
import io.dronefleet.mavlink.ardupilotmega.CameraFeedback
import io.dronefleet.mavlink.common.CameraImageCaptured
import io.dronefleet.mavlink.common.DistanceSensor
import io.dronefleet.mavlink.common.ExtendedSysState
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.GpsRawInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.common.MissionCurrent
import io.dronefleet.mavlink.common.MissionItemReached
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.common.VfrHud
import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.asSharedFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.units.mps
import pod.core.vehicle.Attitude
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.core.vehicle.Battery
import pod.core.vehicle.FlightMode
import pod.core.vehicle.GpsStatus
import pod.core.vehicle.LandedState
import pod.core.vehicle.LinkQuality
import pod.core.vehicle.Position
import pod.core.vehicle.VehicleIdentity

/**
 * Live telemetry of one vehicle, each value a [StateFlow] that holds the latest report (null until
 * the first one arrives).
 */
public class VehicleTelemetry internal constructor() {
    private val _position = PositionFlow()
    private val _home = MutableStateFlow<Location?>(null)
    private val _attitude = AttitudeFlow()
    private val _battery = BatteryFlow()
    private val _hud = HudFlow()
    private val _mode = MutableStateFlow<FlightMode?>(null)
    private val _armed = MutableStateFlow(false)
    private val _landedState = MutableStateFlow(LandedState.UNDEFINED)
    private val _gps = MutableStateFlow<GpsStatus?>(null)
    private val _systemStatus = MutableStateFlow(pod.mavlink.MavStates.UNINIT)
    private val _linkQuality = LinkQualityFlow()
    private val _missionCurrent = MutableStateFlow<Int?>(null)
    private val _rangefinder = MutableStateFlow<Distance?>(null)
    private val _itemReached = MutableSharedFlow<Int>(extraBufferCapacity = 256, onBufferOverflow = BufferOverflow.DROP_OLDEST)
    private val _imagesCaptured = MutableSharedFlow<CapturedImage>(extraBufferCapacity = 256, onBufferOverflow = BufferOverflow.DROP_OLDEST)
    private val _cameraFeedback = MutableSharedFlow<CapturedImage>(extraBufferCapacity = 256, onBufferOverflow = BufferOverflow.DROP_OLDEST)

    /** Global position, relative altitude, heading and velocity (GLOBAL_POSITION_INT). */
    public val position: StateFlow<Position?> = _position

    /** Home location (HOME_POSITION). */
    public val home: StateFlow<Location?> = _home.asStateFlow()

    /** Roll, pitch and yaw (ATTITUDE). */
    public val attitude: StateFlow<Attitude?> = _attitude

    /** Remaining charge and voltage (SYS_STATUS). */
    public val battery: StateFlow<Battery?> = _battery

    /** Airspeed, groundspeed, climb rate, heading and throttle (VFR_HUD). */
    public val hud: StateFlow<Hud?> = _hud

    /** Flight mode, named for the vehicle's autopilot and airframe (HEARTBEAT). */
    public val mode: StateFlow<FlightMode?> = _mode.asStateFlow()

    /** Whether the motors are armed (HEARTBEAT base_mode). */
    public val armed: StateFlow<Boolean> = _armed.asStateFlow()

    /** On the ground, in the air, taking off or landing (EXTENDED_SYS_STATE). */
    public val landedState: StateFlow<LandedState> = _landedState.asStateFlow()

    /** GPS fix and satellites (GPS_RAW_INT). */
    public val gps: StateFlow<GpsStatus?> = _gps.asStateFlow()

    /** MAV_STATE number from the HEARTBEAT, named in [pod.mavlink.MavStates] (0 uninit, 1 boot, 3 standby, 4 active, …). */
    public val systemStatus: StateFlow<Int> = _systemStatus.asStateFlow()

    /** Frames received and lost, from the vehicle's sequence numbers. */
    public val linkQuality: StateFlow<LinkQuality> = _linkQuality

    /** The mission item the vehicle is flying or will fly next (MISSION_CURRENT). */
    public val missionCurrent: StateFlow<Int?> = _missionCurrent.asStateFlow()

    /**
     * Height above the ground from a downward rangefinder (DISTANCE_SENSOR with orientation
     * MAV_SENSOR_ROTATION_PITCH_270): null until one reports, and null while its latest reading
     * lies outside the sensor's own min..max distance (beyond max, ArduPilot's lidar drivers report
     * max + 1 m: "nothing in range", not a height). Sensors facing any other way are ignored.
     */
    public val rangefinder: StateFlow<Distance?> = _rangefinder.asStateFlow()

    /** Each mission item the vehicle reports reached (MISSION_ITEM_REACHED), as it happens. */
    public val itemReached: SharedFlow<Int> = _itemReached.asSharedFlow()

    /**
     * Each photo the autopilot reports taken (CAMERA_IMAGE_CAPTURED from the autopilot's own
     * component, as ArduPilot's AP_Camera sends it), as it happens. Pod's simulator puts what a
     * photo detected in [CapturedImage.fileUrl] (see pod.sim.SimDetections).
     */
    public val imagesCaptured: SharedFlow<CapturedImage> = _imagesCaptured.asSharedFlow()

    /**
     * Each photo the autopilot reports triggering with CAMERA_FEEDBACK (180), as it happens: what
     * ArduPilot 4.7 sends for its own camera instead of CAMERA_IMAGE_CAPTURED
     * (libraries/AP_Camera/AP_Camera_Backend.cpp, prep_mavlink_msg_camera_feedback). The image
     * number is ArduPilot's (from 1), [CapturedImage.timeBootMs] is 0 (the message has UTC time only),
     * [CapturedImage.fileUrl] is empty and [CapturedImage.success] true (it says only that the camera
     * was triggered).
     */
    public val cameraFeedback: SharedFlow<CapturedImage> = _cameraFeedback.asSharedFlow()

    // What the modes below were decoded for: a heartbeat that repeats them decodes nothing, and a
    // mode seen before (GUIDED, then AUTO, then GUIDED again) is the object made the first time.
    private var modeAutopilot: Autopilot? = null
    private var modeType: VehicleType? = null
    private val seenModes = arrayOfNulls<FlightMode>(8)
    private var nextSeen = 0

    /** The mode [customMode] names for [identity], reusing one of the last [seenModes] when it is one. */
    private fun modeOf(identity: VehicleIdentity, customMode: Long): FlightMode {
        if (modeAutopilot !== identity.autopilot || modeType !== identity.type) {
            seenModes.fill(null)
            modeAutopilot = identity.autopilot
            modeType = identity.type
        }
        for (seen in seenModes) if (seen != null && seen.customMode == customMode) return seen
        val mode = FlightModes.decode(identity.autopilot, identity.type, customMode)
        seenModes[nextSeen] = mode
        nextSeen = (nextSeen + 1) % seenModes.size
        return mode
    }

    /**
     * Applies one HEARTBEAT of the vehicle's own component: custom_mode, base_mode and
     * system_status as on the wire. Allocates only for a mode not among the last few seen.
     */
    internal fun onHeartbeat(identity: VehicleIdentity, customMode: Long, baseMode: Int, systemStatus: Int) {
        val mode = _mode.value
        if (mode == null || mode.customMode != customMode || modeAutopilot !== identity.autopilot || modeType !== identity.type) {
            _mode.value = modeOf(identity, customMode)
        }
        _armed.value = baseMode and MAV_MODE_FLAG_SAFETY_ARMED != 0
        if (_systemStatus.value != systemStatus) _systemStatus.value = systemStatus
    }

    /** Applies GLOBAL_POSITION_INT's fields (see [PositionFlow.update]); false when the position is impossible. */
    internal fun onGlobalPosition(lat: Int, lon: Int, alt: Int, relativeAlt: Int, vx: Int, vy: Int, vz: Int, hdg: Int): Boolean =
        _position.update(lat, lon, alt, relativeAlt, vx, vy, vz, hdg)

    /** Applies ATTITUDE's roll, pitch and yaw, in radians. */
    internal fun onAttitude(roll: Float, pitch: Float, yaw: Float) {
        _attitude.update(roll, pitch, yaw)
    }

    /** Applies SYS_STATUS's battery_remaining (%) and voltage_battery (mV). */
    internal fun onSysStatus(batteryRemaining: Int, voltageBattery: Int) {
        _battery.update(batteryRemaining, voltageBattery)
    }

    /** Applies VFR_HUD's fields as on the wire. */
    internal fun onHud(airspeed: Float, groundspeed: Float, alt: Float, climb: Float, heading: Int, throttle: Int) {
        _hud.update(airspeed, groundspeed, alt, climb, heading, throttle)
    }

    /** Applies one decoded message; returns false when it carried nothing usable (out-of-range values). */
    internal fun onMessage(message: Any): Boolean {
        when (message) {
            // The five hot messages usually arrive as fields read in place (MavlinkVehicle.onHotFrame);
            // as objects (an exchange listening, a signed link) they take the same setters.
            is GlobalPositionInt -> return onGlobalPosition(
                message.lat(), message.lon(), message.alt(), message.relativeAlt(),
                message.vx(), message.vy(), message.vz(), message.hdg(),
            )
            is SysStatus -> onSysStatus(message.batteryRemaining(), message.voltageBattery())
            is VfrHud -> onHud(message.airspeed(), message.groundspeed(), message.alt(), message.climb(), message.heading(), message.throttle())
            is HomePosition -> {
                val lat = message.latitude() / 1e7
                val lon = message.longitude() / 1e7
                if (lat !in -90.0..90.0 || lon !in -180.0..180.0) return false
                _home.value = Location(lat, lon, (message.altitude() / 1000.0).m)
            }
            is AttitudeMessage -> onAttitude(message.roll(), message.pitch(), message.yaw())
            is ExtendedSysState -> _landedState.value =
                LandedState.entries.getOrElse(message.landedState().value()) { LandedState.UNDEFINED }
            is MissionCurrent -> _missionCurrent.value = message.seq()
            is MissionItemReached -> _itemReached.tryEmit(message.seq())
            is CameraImageCaptured -> return photo(_imagesCaptured, message.lat(), message.lon(), message.alt() / 1000.0, message.relativeAlt() / 1000.0) { at, relative ->
                CapturedImage(message.imageIndex(), message.timeBootMs(), at, relative, message.captureResult() == 1, message.fileUrl() ?: "")
            }
            // CAMERA_FEEDBACK carries UTC time (GPS), not time since boot, and says only that the camera was triggered.
            is CameraFeedback -> return photo(_cameraFeedback, message.lat(), message.lng(), message.altMsl().toDouble(), message.altRel().toDouble()) { at, relative ->
                CapturedImage(message.imgIdx(), 0, at, relative, success = true, fileUrl = "")
            }
            is DistanceSensor -> {
                if (message.orientation().value() != MAV_SENSOR_ROTATION_PITCH_270) return true
                val cm = message.currentDistance()
                _rangefinder.value = if (cm in message.minDistance()..message.maxDistance()) (cm / 100.0).m else null
            }
            is GpsRawInt -> _gps.value = GpsStatus(
                fixType = message.fixType().value(),
                satellites = message.satellitesVisible().takeIf { it != UNKNOWN_U8 },
            )
        }
        return true
    }

    /** Emits the photo [build] makes at [latE7]/[lonE7] (degrees × 1e7) to [flow]; false when the position is nonsense. */
    private inline fun photo(
        flow: MutableSharedFlow<CapturedImage>, latE7: Int, lonE7: Int, altitude: Double, relative: Double,
        build: (Location, Distance) -> CapturedImage,
    ): Boolean {
        val lat = latE7 / 1e7
        val lon = lonE7 / 1e7
        if (lat !in -90.0..90.0 || lon !in -180.0..180.0) return false
        flow.tryEmit(build(Location(lat, lon, altitude.m), relative.m))
        return true
    }

    internal fun onLinkQuality(received: Long, lost: Long) {
        _linkQuality.update(received, lost)
    }

    private companion object {
        const val MAV_MODE_FLAG_SAFETY_ARMED = 128
        const val UNKNOWN_U16 = 65535
        const val UNKNOWN_U8 = 255
        /** MAV_SENSOR_ORIENTATION: facing down. */
        const val MAV_SENSOR_ROTATION_PITCH_270 = 25
    }
}
