package pod.sim

import pod.mavlink.command.CommandResult
import pod.mavlink.MessageIds
import pod.core.vehicle.Severity
import io.dronefleet.mavlink.common.Attitude
import io.dronefleet.mavlink.common.AutopilotVersion
import io.dronefleet.mavlink.common.CameraInformation
import io.dronefleet.mavlink.common.CameraImageCaptured
import io.dronefleet.mavlink.ardupilotmega.CameraFeedback
import io.dronefleet.mavlink.ardupilotmega.CameraFeedbackFlags
import io.dronefleet.mavlink.common.CommandAck
import io.dronefleet.mavlink.common.DistanceSensor
import io.dronefleet.mavlink.common.MavDistanceSensor
import io.dronefleet.mavlink.common.MavSensorOrientation
import io.dronefleet.mavlink.common.ExtendedSysState
import io.dronefleet.mavlink.common.FenceBreach
import io.dronefleet.mavlink.common.FenceMitigate
import io.dronefleet.mavlink.common.FenceStatus
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.GpsFixType
import io.dronefleet.mavlink.common.GpsRawInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.common.MavCmd
import io.dronefleet.mavlink.common.MavLandedState
import io.dronefleet.mavlink.common.MavParamType
import io.dronefleet.mavlink.common.MavProtocolCapability
import io.dronefleet.mavlink.common.MavResult
import io.dronefleet.mavlink.common.MavSeverity
import io.dronefleet.mavlink.common.MavSysStatusSensor
import io.dronefleet.mavlink.common.MavVtolState
import io.dronefleet.mavlink.common.MissionCurrent
import io.dronefleet.mavlink.common.MissionItemReached
import io.dronefleet.mavlink.common.ParamValue
import io.dronefleet.mavlink.common.Statustext
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.common.VfrHud
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.util.EnumValue
import java.math.BigInteger
import kotlin.math.roundToInt
import kotlin.math.roundToLong
import kotlin.time.TimeMark
import pod.sim.autopilot.profile.AutopilotProfile
import pod.sim.autopilot.profile.TextIds
import pod.core.vehicle.LandedState
import pod.mavlink.MavlinkEnums
import pod.sim.autopilot.SimOutput
import pod.sim.autopilot.SimParameters
import pod.sim.autopilot.packVoltage

/** Builds the messages a simulated vehicle streams from its [SimState]; [missionTotal] counts the mission's items for MISSION_CURRENT. */
internal class SimMessages(
    private val config: SimVehicleConfig,
    private val bootedAt: TimeMark,
    private val missionTotal: () -> Int = { 0 },
) {
    private val profile = AutopilotProfile.of(config.autopilot, config.type)
    private val textIds = TextIds()

    fun canBuild(messageId: Int): Boolean = messageId in SUPPORTED

    fun build(messageId: Int, s: SimState): Any? = when (messageId) {
        MessageIds.SYS_STATUS -> sysStatus(s)
        MessageIds.GPS_RAW_INT -> gpsRaw(s)
        MessageIds.ATTITUDE -> attitude(s)
        MessageIds.GLOBAL_POSITION_INT -> globalPosition(s)
        MessageIds.HOME_POSITION -> home(s)
        MessageIds.EXTENDED_SYS_STATE -> extendedSysState(s)
        MessageIds.VFR_HUD -> vfrHud(s)
        MessageIds.MISSION_CURRENT -> missionCurrent(s.missionCurrent)
        MessageIds.AUTOPILOT_VERSION -> autopilotVersion()
        MessageIds.CAMERA_INFORMATION -> if (config.camera) cameraInformation() else null
        MessageIds.DISTANCE_SENSOR -> distanceSensor(s)
        else -> null
    }

    /**
     * The downward rangefinder's reading, as GCS_MAVLINK::send_distance_sensor
     * (libraries/GCS_MAVLink/GCS_Common.cpp) fills it: min, max and current distance in cm, the
     * sensor type, id = instance 0, orientation (ROTATION_PITCH_270 = 25, downward), covariance 0
     * ("unknown" in ArduPilot's use), no field of view or quaternion, signal quality 0 (unknown).
     * Nothing without a rangefinder: neither autopilot sends DISTANCE_SENSOR with no sensor.
     */
    private fun distanceSensor(s: SimState): DistanceSensor? {
        val sensor = config.rangefinder ?: return null
        fun cm(metres: Double) = (metres * 100).roundToInt().coerceIn(0, 65535)
        return DistanceSensor.builder()
            .timeBootMs(timeBootMs())
            .minDistance(cm(sensor.minDistance.meters))
            .maxDistance(cm(sensor.maxDistance.meters))
            .currentDistance(cm(sensor.reading(s.heightAboveGround.meters)))
            .type(MavDistanceSensor.MAV_DISTANCE_SENSOR_LASER)
            .id(0)
            .orientation(MavSensorOrientation.MAV_SENSOR_ROTATION_PITCH_270)
            .covariance(0)
            .quaternion(listOf(0f, 0f, 0f, 0f))
            .signalQuality(0)
            .build()
    }

    /** The simulated camera, as ArduPilot's AP_Camera describes one: vendor and model, sizes unknown (0). */
    private fun cameraInformation(): CameraInformation = CameraInformation.builder()
        .timeBootMs(timeBootMs())
        .vendorName("Pod".toByteArray().copyOf(32))
        .modelName("sim camera".toByteArray().copyOf(32))
        .build()

    /**
     * What the autopilot can do: MISSION_ITEM_INT, COMMAND_INT, MAVLink 2, fences and rally points,
     * and how it packs integer parameters, with the version it claims to behave like (both its
     * profile's: C cast on ArduPilot 4.7.0, bytewise on PX4 1.16.0, official releases).
     */
    private fun autopilotVersion(): AutopilotVersion {
        val (major, minor) = profile.version
        return AutopilotVersion.builder()
            .capabilities(EnumValue.create<MavProtocolCapability>(CAPABILITIES or profile.paramEncodingCapability))
            .flightSwVersion((major.toLong() shl 24) or (minor.toLong() shl 16) or OFFICIAL_RELEASE)
            .uid(BigInteger.valueOf(config.systemId.toLong()))
            .build()
    }

    /** STATUSTEXT for [text], cut into 50-character chunks with ids as its profile's firmware does. */
    fun statusTexts(severity: Severity, text: String): List<Statustext> {
        // MAV_SEVERITY numbers are the core enum's order, EMERGENCY 0 to DEBUG 7.
        val level = EnumValue.create<MavSeverity>(severity.ordinal)
        return profile.statusTextChunks(text, textIds).map { Statustext.builder().severity(level).text(it.text).id(it.id).chunkSeq(it.seq).build() }
    }

    /** The messages for one of the autopilot's [SimOutput]s (several for a long text). */
    fun outputs(out: SimOutput, s: SimState, params: SimParameters): List<Any> = when (out) {
        is SimOutput.Text -> statusTexts(out.severity, out.text)
        is SimOutput.Photo -> photoReports(out.photo, s)
        else -> listOfNotNull(output(out, s, params))
    }

    /**
     * What the vehicle sends for a photo it took.
     *
     * Where the profile reports CAMERA_FEEDBACK (ArduPilot 4.7's own camera backends), it queues
     * MSG_CAMERA_FEEDBACK on every link (GCS_SEND_MESSAGE) with img_idx counted from 1
     * (libraries/AP_Camera/AP_Camera_Backend.cpp; SITL, CAM1_TYPE 1: IMAGE_START_CAPTURE ACCEPTED,
     * then only CAMERA_FEEDBACK). A scenario with objects to detect stands for a companion computer
     * that reports what it saw: its CAMERA_IMAGE_CAPTURED carries the detections ([SimDetections])
     * just before the autopilot's CAMERA_FEEDBACK. PX4's MAVLink camera answers with
     * CAMERA_IMAGE_CAPTURED.
     */
    private fun photoReports(photo: PhotoEvent, s: SimState): List<Any> {
        if (!profile.reportsCameraFeedback) return listOf(imageCaptured(photo, s))
        val feedback = CameraFeedback.builder()
            .timeUsec(BigInteger.valueOf(photo.time.inWholeMicroseconds))
            .camIdx(0)
            .imgIdx(photo.index + 1)
            .lat(e7(photo.location.latitude))
            .lng(e7(photo.location.longitude))
            .altMsl(photo.location.altitude.meters.toFloat())
            .altRel((photo.location.altitude.meters - s.home.altitude.meters).toFloat())
            .yaw(photo.heading.degrees.toFloat())
            .flags(CameraFeedbackFlags.CAMERA_FEEDBACK_PHOTO)
            .build()
        return if (config.objects.isEmpty()) listOf(feedback) else listOf(imageCaptured(photo, s), feedback)
    }

    private fun imageCaptured(photo: PhotoEvent, s: SimState): CameraImageCaptured = CameraImageCaptured.builder()
        .timeBootMs(photo.time.inWholeMilliseconds)
        .timeUtc(BigInteger.ZERO)
        .cameraId(0)
        .lat(e7(photo.location.latitude))
        .lon(e7(photo.location.longitude))
        .alt((photo.location.altitude.meters * 1000).roundToInt())
        .relativeAlt(((photo.location.altitude.meters - s.home.altitude.meters) * 1000).roundToInt())
        .q(listOf(1f, 0f, 0f, 0f))
        .imageIndex(photo.index)
        .captureResult(1)
        .fileUrl(SimDetections.fileUrl(photo.index, photo.detected.map { it.id }))
        .build()

    private fun output(out: SimOutput, s: SimState, params: SimParameters): Any? = when (out) {
        is SimOutput.Ack -> CommandAck.builder()
            .command(EnumValue.create<MavCmd>(out.command))
            .result(EnumValue.create<MavResult>(out.result.mavValue))
            .progress(out.progress)
            .targetSystem(out.targetSystem)
            .targetComponent(out.targetComponent)
            .build()
        is SimOutput.Text -> statusTexts(out.severity, out.text).first()
        is SimOutput.ItemReached -> MissionItemReached.builder().seq(out.seq).build()
        is SimOutput.MissionCurrent -> missionCurrent(out.seq)
        is SimOutput.HomeChanged -> home(s) ?: return null
        is SimOutput.Param -> params.at(out.index)!!.let { def ->
            ParamValue.builder()
                .paramId(def.name)
                .paramValue(params.wireValue(out.index))
                .paramType(EnumValue.create<MavParamType>(def.type.mavValue))
                .paramCount(params.count)
                .paramIndex(out.index)
                .build()
        }
        is SimOutput.FenceStatus -> FenceStatus.builder()
            .breachStatus(if (out.breached) 1 else 0)
            .breachCount(out.count)
            .breachType(EnumValue.create<FenceBreach>(out.type))
            .breachTime(out.timeMs)
            .breachMitigation(EnumValue.create<FenceMitigate>(out.mitigation))
            .build()
        is SimOutput.Photo -> imageCaptured(out.photo, s)
    }

    private fun missionCurrent(seq: Int): MissionCurrent = MissionCurrent.builder().seq(seq).total(missionTotal()).build()

    private fun vfrHud(s: SimState): VfrHud = VfrHud.builder()
        .airspeed(s.airspeed.metersPerSecond.toFloat())
        .groundspeed(s.groundSpeed.metersPerSecond.toFloat())
        .heading(s.heading.degrees.roundToInt().mod(360))
        .throttle(s.throttle)
        .alt(s.location.altitude.meters.toFloat())
        .climb(s.climbRate.metersPerSecond.toFloat())
        .build()

    fun heartbeat(s: SimState): Heartbeat = Heartbeat.builder()
        .type(EnumValue.create(MavlinkEnums.mavType(config.type)))
        .autopilot(EnumValue.create(MavlinkEnums.mavAutopilot(config.autopilot)))
        .baseMode(EnumValue.create(MODE_FLAG_CUSTOM_MODE_ENABLED or (if (s.armed) MODE_FLAG_SAFETY_ARMED else 0)))
        .customMode(s.customMode)
        .systemStatus(if (s.armed) MavState.MAV_STATE_ACTIVE else MavState.MAV_STATE_STANDBY)
        .mavlinkVersion(3)
        .build()

    private fun timeBootMs(): Long = bootedAt.elapsedNow().inWholeMilliseconds and 0xFFFF_FFFFL

    // Sensors a ground station checks before flight (MAVSDK's health flags come from these bits):
    // present and enabled always; GPS healthy once it has a fix, pre-arm checks once it could arm.
    private fun sysStatus(s: SimState): SysStatus = SysStatus.builder()
        .onboardControlSensorsPresent(EnumValue.create<MavSysStatusSensor>(SENSORS or SENSOR_PREARM_CHECK))
        .onboardControlSensorsEnabled(EnumValue.create<MavSysStatusSensor>(SENSORS or SENSOR_PREARM_CHECK))
        .onboardControlSensorsHealth(
            EnumValue.create<MavSysStatusSensor>(
                (SENSORS and SENSOR_GPS.inv()) or (if (s.positionReady) SENSOR_GPS or SENSOR_PREARM_CHECK else 0),
            ),
        )
        .voltageBattery((packVoltage(s.charge) * 1000).roundToInt())
        .currentBattery(if (s.armed) 1500 else 0) // cA: 15 A hovering
        .batteryRemaining((s.charge * 100).roundToInt())
        .build()

    private fun gpsRaw(s: SimState): GpsRawInt = GpsRawInt.builder()
        .timeUsec(BigInteger.valueOf(bootedAt.elapsedNow().inWholeMicroseconds))
        .fixType(if (s.positionReady) GpsFixType.GPS_FIX_TYPE_3D_FIX else GpsFixType.GPS_FIX_TYPE_NO_FIX)
        .lat(e7(s.location.latitude))
        .lon(e7(s.location.longitude))
        .alt((s.location.altitude.meters * 1000).roundToInt())
        .eph(80)
        .epv(120)
        .vel(65535)
        .cog(65535)
        .satellitesVisible(if (s.positionReady) 14 else 3)
        .build()

    private fun attitude(s: SimState): Attitude = Attitude.builder()
        .timeBootMs(timeBootMs())
        .yaw(Math.toRadians(s.heading.degrees.let { if (it > 180) it - 360 else it }).toFloat())
        .build()

    private fun globalPosition(s: SimState): GlobalPositionInt = GlobalPositionInt.builder()
        .timeBootMs(timeBootMs())
        .lat(e7(s.location.latitude))
        .lon(e7(s.location.longitude))
        .alt((s.location.altitude.meters * 1000).roundToInt())
        .relativeAlt((s.relativeAltitude.meters * 1000).roundToInt())
        .vx((s.velocityNed.first.metersPerSecond * 100).roundToInt())
        .vy((s.velocityNed.second.metersPerSecond * 100).roundToInt())
        .vz((s.velocityNed.third.metersPerSecond * 100).roundToInt())
        .hdg((s.heading.degrees * 100).roundToInt().mod(36000))
        .build()

    /** Nothing before the estimator's origin (and so home) is set, as GCS_MAVLINK::send_home_position. */
    private fun home(s: SimState): HomePosition? = if (!s.positionReady) null else HomePosition.builder()
        .latitude(e7(s.home.latitude))
        .longitude(e7(s.home.longitude))
        .altitude((s.home.altitude.meters * 1000).roundToInt())
        .q(listOf(1f, 0f, 0f, 0f))
        .build()

    private fun extendedSysState(s: SimState): ExtendedSysState = ExtendedSysState.builder()
        .vtolState(MavVtolState.MAV_VTOL_STATE_UNDEFINED)
        .landedState(
            when (s.landedState) {
                LandedState.UNDEFINED -> MavLandedState.MAV_LANDED_STATE_UNDEFINED
                LandedState.ON_GROUND -> MavLandedState.MAV_LANDED_STATE_ON_GROUND
                LandedState.IN_AIR -> MavLandedState.MAV_LANDED_STATE_IN_AIR
                LandedState.TAKEOFF -> MavLandedState.MAV_LANDED_STATE_TAKEOFF
                LandedState.LANDING -> MavLandedState.MAV_LANDED_STATE_LANDING
            },
        )
        .build()

    private fun e7(degrees: Double): Int = (degrees * 1e7).roundToLong().toInt()

    private companion object {
        val SUPPORTED = setOf(
            MessageIds.SYS_STATUS, MessageIds.GPS_RAW_INT, MessageIds.ATTITUDE,
            MessageIds.GLOBAL_POSITION_INT, MessageIds.HOME_POSITION, MessageIds.EXTENDED_SYS_STATE,
            MessageIds.VFR_HUD, MessageIds.MISSION_CURRENT, MessageIds.AUTOPILOT_VERSION,
            // Accepted with or without a sensor, as both autopilots accept an interval for a message they know.
            MessageIds.DISTANCE_SENSOR,
        )
        /** MISSION_INT, COMMAND_INT, MAVLINK2, MISSION_FENCE, MISSION_RALLY (MAV_PROTOCOL_CAPABILITY bits). */
        const val CAPABILITIES = 0x4 or 0x8 or 0x2000 or 0x4000 or 0x8000
        /** FIRMWARE_VERSION_TYPE_OFFICIAL in the low byte of flight_sw_version. */
        const val OFFICIAL_RELEASE = 255L
        const val SENSOR_GPS = 0x20
        const val SENSOR_PREARM_CHECK = 0x1000_0000
        /** Gyro, accelerometer, magnetometer, barometer, GPS, motor outputs, battery (MAV_SYS_STATUS_SENSOR bits). */
        const val SENSORS = 0x1 or 0x2 or 0x4 or 0x8 or SENSOR_GPS or 0x8000 or 0x200_0000
        const val MODE_FLAG_CUSTOM_MODE_ENABLED = 1
        const val MODE_FLAG_SAFETY_ARMED = 128
    }
}
