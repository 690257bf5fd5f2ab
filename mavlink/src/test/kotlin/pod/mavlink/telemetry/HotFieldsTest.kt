package pod.mavlink.telemetry

import io.dronefleet.mavlink.common.Attitude
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.common.VfrHud
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.serialization.payload.reflection.ReflectionPayloadDeserializer
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.byte
import io.kotest.property.arbitrary.byteArray
import io.kotest.property.arbitrary.constant
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll
import pod.mavlink.MessageIds
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame

/**
 * The in-place readers of the five hot messages against io.dronefleet's own decoder, field by
 * field, on random payload bytes framed and parsed as the station parses them: MAVLink 2 frames
 * truncated anywhere (the missing bytes read as zero, as the spec says; io.dronefleet is given them
 * zero-filled) and MAVLink 1 frames at their full MAVLink 1 length.
 */
class HotFieldsTest : StringSpec({
    val reflective = ReflectionPayloadDeserializer()
    val encoder = FrameEncoder()

    /** Parses one frame of [payload] as message [id] through a FrameDecoder and reads it with [read]. */
    fun <T> parsed(id: Int, payload: ByteArray, version: Int, read: (pod.mavlink.codec.FrameView) -> T): T {
        val wire = encoder.encode(MavFrame(version, 7, 1, 1, id, payload))
        var result: T? = null
        FrameDecoder().feedViews(wire, 0, wire.size) { view -> result = read(view) }
        return checkNotNull(result) { "no frame parsed" }
    }

    /** Random payloads of [id]: MAVLink 2 cut to any length 1..[fullLength], or MAVLink 1 at [v1Length]. */
    suspend fun forPayloads(id: Int, fullLength: Int, v1Length: Int, check: (payload: ByteArray, version: Int, full: ByteArray) -> Unit) {
        checkAll(300, Arb.element(1, 2), Arb.int(1..fullLength), Arb.byteArray(Arb.constant(fullLength), Arb.byte())) { version, cut, bytes ->
            val length = if (version == 1) v1Length else cut
            val payload = bytes.copyOf(length)
            withClue("MAVLink $version, ${payload.size} of $fullLength bytes: ${payload.joinToString(",")}") {
                check(payload, version, payload.copyOf(fullLength))
            }
        }
    }

    fun bits(value: Float): Int = java.lang.Float.floatToIntBits(value)

    fun u32(value: Int): Long = value.toLong() and 0xFFFF_FFFFL

    "HEARTBEAT is read as io.dronefleet reads it" {
        forPayloads(MessageIds.HEARTBEAT, 9, 9) { payload, version, full ->
            val f = parsed(MessageIds.HEARTBEAT, payload, version) { HeartbeatFields().apply { read(it) } }
            val m = reflective.deserialize(full, Heartbeat::class.java)
            listOf(f.customMode, f.type, f.autopilot, f.baseMode, f.systemStatus, f.mavlinkVersion) shouldBe
                listOf(m.customMode(), m.type().value(), m.autopilot().value(), m.baseMode().value(), m.systemStatus().value(), m.mavlinkVersion())
        }
    }

    "SYS_STATUS, extensions included, is read as io.dronefleet reads it" {
        forPayloads(MessageIds.SYS_STATUS, 43, 31) { payload, version, full ->
            val f = parsed(MessageIds.SYS_STATUS, payload, version) { SysStatusFields().apply { read(it) } }
            val m = reflective.deserialize(full, SysStatus::class.java)
            listOf(
                f.sensorsPresent, f.sensorsEnabled, f.sensorsHealth, f.load, f.voltageBattery, f.currentBattery, f.dropRateComm,
                f.errorsComm, f.errorsCount1, f.errorsCount2, f.errorsCount3, f.errorsCount4, f.batteryRemaining,
                f.sensorsPresentExtended, f.sensorsEnabledExtended, f.sensorsHealthExtended,
            ) shouldBe listOf(
                u32(m.onboardControlSensorsPresent().value()), u32(m.onboardControlSensorsEnabled().value()), u32(m.onboardControlSensorsHealth().value()),
                m.load(), m.voltageBattery(), m.currentBattery(), m.dropRateComm(), m.errorsComm(),
                m.errorsCount1(), m.errorsCount2(), m.errorsCount3(), m.errorsCount4(), m.batteryRemaining(),
                u32(m.onboardControlSensorsPresentExtended().value()), u32(m.onboardControlSensorsEnabledExtended().value()),
                u32(m.onboardControlSensorsHealthExtended().value()),
            )
        }
    }

    "ATTITUDE is read as io.dronefleet reads it" {
        forPayloads(MessageIds.ATTITUDE, 28, 28) { payload, version, full ->
            val f = parsed(MessageIds.ATTITUDE, payload, version) { AttitudeFields().apply { read(it) } }
            val m = reflective.deserialize(full, Attitude::class.java)
            listOf(f.timeBootMs, bits(f.roll).toLong(), bits(f.pitch).toLong(), bits(f.yaw).toLong(), bits(f.rollSpeed).toLong(), bits(f.pitchSpeed).toLong(), bits(f.yawSpeed).toLong()) shouldBe
                listOf(m.timeBootMs(), bits(m.roll()).toLong(), bits(m.pitch()).toLong(), bits(m.yaw()).toLong(), bits(m.rollspeed()).toLong(), bits(m.pitchspeed()).toLong(), bits(m.yawspeed()).toLong())
        }
    }

    "GLOBAL_POSITION_INT is read as io.dronefleet reads it" {
        forPayloads(MessageIds.GLOBAL_POSITION_INT, 28, 28) { payload, version, full ->
            val f = parsed(MessageIds.GLOBAL_POSITION_INT, payload, version) { GlobalPositionFields().apply { read(it) } }
            val m = reflective.deserialize(full, GlobalPositionInt::class.java)
            listOf(f.timeBootMs, f.lat.toLong(), f.lon.toLong(), f.alt.toLong(), f.relativeAlt.toLong(), f.vx.toLong(), f.vy.toLong(), f.vz.toLong(), f.hdg.toLong()) shouldBe
                listOf(m.timeBootMs(), m.lat().toLong(), m.lon().toLong(), m.alt().toLong(), m.relativeAlt().toLong(), m.vx().toLong(), m.vy().toLong(), m.vz().toLong(), m.hdg().toLong())
        }
    }

    "VFR_HUD is read as io.dronefleet reads it" {
        forPayloads(MessageIds.VFR_HUD, 20, 20) { payload, version, full ->
            val f = parsed(MessageIds.VFR_HUD, payload, version) { VfrHudFields().apply { read(it) } }
            val m = reflective.deserialize(full, VfrHud::class.java)
            listOf(bits(f.airspeed), bits(f.groundspeed), bits(f.alt), bits(f.climb), f.heading, f.throttle) shouldBe
                listOf(bits(m.airspeed()), bits(m.groundspeed()), bits(m.alt()), bits(m.climb()), m.heading(), m.throttle())
        }
    }
})
