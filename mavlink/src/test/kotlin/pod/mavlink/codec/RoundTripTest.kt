package pod.mavlink.codec

import io.dronefleet.mavlink.common.Attitude
import io.dronefleet.mavlink.common.BatteryStatus
import io.dronefleet.mavlink.common.CommandAck
import io.dronefleet.mavlink.common.CommandInt
import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.ExtendedSysState
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.GpsRawInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.common.MissionAck
import io.dronefleet.mavlink.common.MissionClearAll
import io.dronefleet.mavlink.common.MissionCount
import io.dronefleet.mavlink.common.MissionCurrent
import io.dronefleet.mavlink.common.MissionItemInt
import io.dronefleet.mavlink.common.MissionItemReached
import io.dronefleet.mavlink.common.MissionRequest
import io.dronefleet.mavlink.common.MissionRequestInt
import io.dronefleet.mavlink.common.MissionRequestList
import io.dronefleet.mavlink.common.MissionSetCurrent
import io.dronefleet.mavlink.common.ParamRequestRead
import io.dronefleet.mavlink.common.ParamSet
import io.dronefleet.mavlink.common.ParamValue
import io.dronefleet.mavlink.common.RcChannels
import io.dronefleet.mavlink.common.RequestDataStream
import io.dronefleet.mavlink.common.SetMode
import io.dronefleet.mavlink.common.Statustext
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.common.SystemTime
import io.dronefleet.mavlink.common.Timesync
import io.dronefleet.mavlink.common.VfrHud
import io.dronefleet.mavlink.minimal.Heartbeat
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.ints.shouldBeInRange
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.checkAll

/** The message classes a ground station exchanges with ArduPilot and PX4. */
internal val gcsMessages: List<Class<*>> = listOf(
    Heartbeat::class.java, SysStatus::class.java, GlobalPositionInt::class.java, Attitude::class.java,
    MissionCurrent::class.java, HomePosition::class.java, CommandLong::class.java, CommandAck::class.java,
    Statustext::class.java, MissionItemInt::class.java, MissionCount::class.java, MissionRequestInt::class.java,
    MissionAck::class.java, ParamValue::class.java, GpsRawInt::class.java, BatteryStatus::class.java,
    ExtendedSysState::class.java, SetMode::class.java, ParamRequestRead::class.java, ParamSet::class.java,
    MissionRequestList::class.java, MissionClearAll::class.java, MissionSetCurrent::class.java,
    MissionItemReached::class.java, RequestDataStream::class.java, SystemTime::class.java, Timesync::class.java,
    VfrHud::class.java, RcChannels::class.java, CommandInt::class.java, MissionRequest::class.java,
)

/** A random message of one of [classes], ready for [version] (MAVLink 1 carries no extension fields). */
internal fun messageArb(classes: List<Class<*>>, version: Int): Arb<Any> = arbitrary { rs ->
    TestMessages.random(classes.random(rs.random), rs.random, extensions = version == 2)
}

internal class RoundTripTest : FunSpec({
    val codec = MessageCodec.Default
    val encoder = FrameEncoder(codec)

    fun roundTrip(message: Any, version: Int, sequence: Int = 7): Any? {
        val wire = encoder.encode(message, systemId = 1, componentId = 190, sequence = sequence, version = version)
        val decoder = FrameDecoder(codec)
        val frames = decoder.decodeAll(wire)
        withClue("$message as v$version: ${wire.toHex()}") {
            frames shouldHaveSize 1
            decoder.stats.badCrc shouldBe 0
            frames.single().version shouldBe version
            frames.single().sequence shouldBe sequence
        }
        return codec.decode(frames.single())
    }

    for (version in 1..2) {
        for (messageClass in gcsMessages) {
            test("${messageClass.simpleName} survives a MAVLink $version round trip with random values") {
                checkAll(150, messageArb(listOf(messageClass), version)) { message ->
                    roundTrip(message, version) shouldBe message
                }
            }
        }
    }

    test("every message of the dialect survives a round trip in both versions") {
        val classes = codec.messageClasses
        classes.size shouldBeGreaterThan 250
        for (messageClass in classes) {
            val versions = if (codec.messageId(messageClass) <= 255) 1..2 else 2..2
            for (version in versions) {
                checkAll(15, messageArb(listOf(messageClass), version)) { message ->
                    withClue(messageClass.simpleName) { roundTrip(message, version) shouldBe message }
                }
            }
        }
    }

    test("MAVLink 2 payloads lose their trailing zeros but keep one byte; MAVLink 1 payloads keep all base fields") {
        checkAll(500, messageArb(gcsMessages, 2)) { message ->
            val full = codec.encodePayload(message)
            val wire = encoder.encode(message, 1, 1, 0, version = 2)
            val length = wire[1].toInt() and 0xFF
            length shouldBeInRange 1..full.size
            full.copyOfRange(0, length).toHex() shouldBe wire.copyOfRange(10, 10 + length).toHex()
            full.drop(length).all { it.toInt() == 0 } shouldBe true
            if (length > 1) (full[length - 1].toInt() == 0) shouldBe false

            val plan = codec.planOf(message.javaClass)
            if (plan.id <= 255) (encoder.encode(message, 1, 1, 0, version = 1)[1].toInt() and 0xFF) shouldBe plan.baseLength
        }
    }
})
