package pod.bench

import io.dronefleet.mavlink.annotations.MavlinkMessageInfo
import io.dronefleet.mavlink.common.Attitude
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.MavSysStatusSensor
import io.dronefleet.mavlink.common.MavSysStatusSensorExtended
import io.dronefleet.mavlink.common.MissionCurrent
import io.dronefleet.mavlink.common.MissionState
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.protocol.MavlinkPacket
import io.dronefleet.mavlink.serialization.payload.reflection.ReflectionPayloadSerializer
import io.dronefleet.mavlink.util.EnumValue

/**
 * The messages every benchmark decodes, and their wire bytes.
 *
 * The bytes are built with io.dronefleet's serializer and packet writer, not with Pod's
 * [pod.mavlink.codec.FrameEncoder]: the decoder under test should not read bytes that its own
 * encoder wrote (a shared misunderstanding would go unnoticed), and the fixtures then exist before
 * Pod's codec does. pymavlink decodes the same bytes with its CRC check on, which vouches for them.
 */
object Fixtures {

    /** Sender identity used in every fixture frame (an ArduPilot autopilot component). */
    const val SYSTEM_ID = 1
    const val COMPONENT_ID = 1

    /** Messages benchmarked, by MAVLink name; values are realistic and mostly non-zero so that no field is trivially empty. */
    enum class Sample(val build: () -> Any) {
        HEARTBEAT({
            Heartbeat.builder()
                .type(MavType.MAV_TYPE_QUADROTOR)
                .autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
                .baseMode(EnumValue.create(MODE_FLAG_CUSTOM_MODE_ENABLED or MODE_FLAG_SAFETY_ARMED or MODE_FLAG_STABILIZE_ENABLED))
                .customMode(4) // ArduCopter GUIDED
                .systemStatus(MavState.MAV_STATE_ACTIVE)
                .mavlinkVersion(3)
                .build()
        }),
        SYS_STATUS({
            // The extended sensor bitmaps (MAVLink 2 extensions) are zero, so they are truncated
            // off the wire as ArduPilot does. They are set explicitly: a decoder yields 0 for them,
            // and the builder's default (null) would not compare equal to that.
            val sensors = EnumValue.create<MavSysStatusSensor>(0x3520_FC2F)
            val noExtendedSensors = EnumValue.create<MavSysStatusSensorExtended>(0)
            SysStatus.builder()
                .onboardControlSensorsPresent(sensors)
                .onboardControlSensorsEnabled(sensors)
                .onboardControlSensorsHealth(sensors)
                .load(312)
                .voltageBattery(15_840)
                .currentBattery(1_530)
                .batteryRemaining(78)
                .dropRateComm(3)
                .errorsComm(17)
                .onboardControlSensorsPresentExtended(noExtendedSensors)
                .onboardControlSensorsEnabledExtended(noExtendedSensors)
                .onboardControlSensorsHealthExtended(noExtendedSensors)
                .build()
        }),
        ATTITUDE({
            Attitude.builder()
                .timeBootMs(1_234_567)
                .roll(0.0523f)
                .pitch(-0.0311f)
                .yaw(2.7412f)
                .rollspeed(0.0012f)
                .pitchspeed(-0.0009f)
                .yawspeed(0.1003f)
                .build()
        }),
        GLOBAL_POSITION_INT({ globalPosition(latitudeE7 = 473_977_418, timeBootMs = 1_234_567) }),
        MISSION_CURRENT({
            MissionCurrent.builder()
                .seq(7)
                .total(23)
                .missionState(MissionState.MISSION_STATE_ACTIVE)
                .missionMode(1)
                .build()
        }),
        ;

        /** The io.dronefleet message object (a new one each call). */
        fun message(): Any = build()

        /** One MAVLink 2 datagram carrying [message] as ([SYSTEM_ID], [COMPONENT_ID]). */
        fun datagram(sequence: Int = 0): ByteArray = mavlink2Datagram(message(), SYSTEM_ID, COMPONENT_ID, sequence)
    }

    /** A GLOBAL_POSITION_INT over Zurich at 48.8 m AMSL, 20 m up, moving north-east. */
    fun globalPosition(latitudeE7: Int, timeBootMs: Long): GlobalPositionInt = GlobalPositionInt.builder()
        .timeBootMs(timeBootMs)
        .lat(latitudeE7)
        .lon(85_455_939)
        .alt(488_120)
        .relativeAlt(20_150)
        .vx(512)
        .vy(-230)
        .vz(15)
        .hdg(27_015)
        .build()

    /** The HEARTBEAT of an armed ArduCopter quadrotor: what makes a Pod ground station create a vehicle. */
    fun vehicleHeartbeat(): Any = Sample.HEARTBEAT.message()

    private val serializer = ReflectionPayloadSerializer()

    /**
     * Wire bytes of one unsigned MAVLink 2 frame carrying [message]. The payload is truncated of
     * trailing zero bytes (keeping one), as MAVLink 2 senders (pymavlink, ArduPilot) do.
     */
    fun mavlink2Datagram(message: Any, systemId: Int, componentId: Int, sequence: Int): ByteArray {
        val info = requireNotNull(message.javaClass.getAnnotation(MavlinkMessageInfo::class.java)) {
            "${message.javaClass.name} is not an io.dronefleet message"
        }
        val full = serializer.serialize(message)
        var length = full.size
        while (length > 1 && full[length - 1] == 0.toByte()) length--
        return MavlinkPacket.createUnsignedMavlink2Packet(
            sequence and 0xFF,
            systemId,
            componentId,
            info.id,
            info.crc,
            full.copyOf(length),
        ).rawBytes
    }

    /** The payload bytes of a MAVLink 2 [datagram] (header is 10 bytes, CRC 2, unsigned). */
    fun payloadOf(datagram: ByteArray): ByteArray {
        require(datagram.size >= MAVLINK2_OVERHEAD && datagram[0] == MAVLINK2_MAGIC) { "not an unsigned MAVLink 2 frame" }
        val length = datagram[1].toInt() and 0xFF
        return datagram.copyOfRange(MAVLINK2_HEADER, MAVLINK2_HEADER + length)
    }

    private const val MAVLINK2_MAGIC = 0xFD.toByte()
    private const val MAVLINK2_HEADER = 10
    private const val MAVLINK2_OVERHEAD = 12
    private const val MODE_FLAG_CUSTOM_MODE_ENABLED = 1
    private const val MODE_FLAG_STABILIZE_ENABLED = 16
    private const val MODE_FLAG_SAFETY_ARMED = 128
}
