package pod.mavlink.fuzz

import io.dronefleet.mavlink.common.Attitude
import io.dronefleet.mavlink.common.CameraImageCaptured
import io.dronefleet.mavlink.common.CommandAck
import io.dronefleet.mavlink.common.CommandInt
import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.DistanceSensor
import io.dronefleet.mavlink.common.ExtendedSysState
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.GpsRawInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.common.MissionAck
import io.dronefleet.mavlink.common.MissionCount
import io.dronefleet.mavlink.common.MissionCurrent
import io.dronefleet.mavlink.common.MissionItemInt
import io.dronefleet.mavlink.common.MissionItemReached
import io.dronefleet.mavlink.common.MissionRequest
import io.dronefleet.mavlink.common.MissionRequestInt
import io.dronefleet.mavlink.common.ParamSet
import io.dronefleet.mavlink.common.ParamValue
import io.dronefleet.mavlink.common.RadioStatus
import io.dronefleet.mavlink.common.SetupSigning
import io.dronefleet.mavlink.common.Statustext
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.common.Timesync
import io.dronefleet.mavlink.common.VfrHud
import io.dronefleet.mavlink.minimal.Heartbeat
import pod.mavlink.codec.Crc
import pod.mavlink.codec.FrameLayout
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec
import pod.mavlink.codec.TestMessages
import pod.mavlink.signing.FrameSignature
import pod.mavlink.signing.SigningKey
import kotlin.random.Random

/**
 * The valid inputs every fuzz target mutates, made once from a seed: each hot message (what a
 * vehicle streams and what the mission, command, parameter and signing exchanges carry) with random
 * field values in MAVLink 1 (when its id fits), MAVLink 2, and MAVLink 2 signed with [key]; one frame
 * of every other message of the dialect; and frames of unknown message ids. Frames are wire bytes.
 */
public class FuzzCorpus(seed: Long) {
    private val codec = MessageCodec.Default
    private val encoder = FrameEncoder(codec)

    /** The key the signed frames are signed with. */
    public val key: SigningKey = SigningKey(Random(seed).nextBytes(SigningKey.SIZE))

    /** Unsigned frames, MAVLink 1 and 2. */
    public val unsigned: List<ByteArray>

    /** MAVLink 2 frames signed with [key] (link ids 0..3, timestamps around 2026). */
    public val signed: List<ByteArray>

    /** Every frame of the corpus. */
    public val frames: List<ByteArray>

    init {
        val random = Random(seed)
        val plain = mutableListOf<ByteArray>()
        val signedFrames = mutableListOf<ByteArray>()
        for (messageClass in HOT) {
            repeat(VARIANTS) {
                val message = TestMessages.random(messageClass, random)
                val v2 = encoder.encode(message, system(random), random.nextInt(256), random.nextInt(256), version = 2)
                plain += v2
                signedFrames += sign(v2, linkId = random.nextInt(4), timestamp = BASE_TIMESTAMP + random.nextInt(1_000_000))
                if (codec.messageId(messageClass) <= 255) {
                    val v1 = TestMessages.random(messageClass, random, extensions = false)
                    plain += encoder.encode(v1, system(random), random.nextInt(256), random.nextInt(256), version = 1)
                }
            }
        }
        for (messageClass in codec.messageClassesForFuzzing()) {
            plain += encoder.encode(TestMessages.random(messageClass, random), system(random), 1, random.nextInt(256))
        }
        repeat(UNKNOWN_IDS) { plain += unknownId(random) }
        unsigned = plain
        signed = signedFrames
        frames = plain + signedFrames
    }

    /**
     * [frame] (an unsigned MAVLink 2 frame) with the signed flag, its CRC redone (the flag is part of
     * the header it covers) and a signature block signed with [key] on [linkId] at [timestamp].
     */
    public fun sign(frame: ByteArray, linkId: Int, timestamp: Long): ByteArray {
        val signed = frame.copyOf(frame.size + FrameLayout.SIGNATURE)
        signed[2] = (signed[2].toInt() or FrameLayout.FLAG_SIGNED).toByte()
        val payload = frame[1].toInt() and 0xFF
        val id = (frame[7].toInt() and 0xFF) or ((frame[8].toInt() and 0xFF) shl 8) or ((frame[9].toInt() and 0xFF) shl 16)
        val crc = Crc.frameChecksum(signed, 1, FrameLayout.HEADER_V2 - 1 + payload, codec.crcExtra(id).coerceAtLeast(0))
        signed[FrameLayout.HEADER_V2 + payload] = crc.toByte()
        signed[FrameLayout.HEADER_V2 + payload + 1] = (crc ushr 8).toByte()
        return FrameSignature.sign(signed, key, linkId, timestamp)
    }

    /** A frame of a message id the dialect does not know, MAVLink 1 or 2, with a random payload. */
    private fun unknownId(random: Random): ByteArray {
        val v1 = random.nextBoolean()
        val id = if (v1) (0..255).filter { codec.crcExtra(it) < 0 }.random(random) else 0x800000 + random.nextInt(0x7FFFFF)
        val frame = MavFrame(if (v1) 1 else 2, random.nextInt(256), system(random), random.nextInt(256), id, random.nextBytes(random.nextInt(256)))
        return encoder.encode(frame)
    }

    /** A system id as a small fleet has them: vehicles 1 to 4 and a ground station 255 (so a log's frames share senders). */
    private fun system(random: Random): Int = SYSTEMS[random.nextInt(SYSTEMS.size)]

    public companion object {
        private val SYSTEMS = intArrayOf(1, 2, 3, 4, 255)

        /** The messages a ground station lives on: each gets [VARIANTS] frames per version. */
        public val HOT: List<Class<*>> = listOf(
            Heartbeat::class.java, SysStatus::class.java, Attitude::class.java, GlobalPositionInt::class.java,
            VfrHud::class.java, GpsRawInt::class.java, HomePosition::class.java, ExtendedSysState::class.java,
            MissionCurrent::class.java, MissionItemReached::class.java, Statustext::class.java,
            DistanceSensor::class.java, CameraImageCaptured::class.java, RadioStatus::class.java,
            CommandLong::class.java, CommandInt::class.java, CommandAck::class.java,
            MissionCount::class.java, MissionRequest::class.java, MissionRequestInt::class.java,
            MissionItemInt::class.java, MissionAck::class.java, ParamValue::class.java, ParamSet::class.java,
            Timesync::class.java, SetupSigning::class.java,
        )

        /** Random frames per hot message and version. */
        public const val VARIANTS: Int = 4

        /** Frames of message ids the dialect does not know. */
        public const val UNKNOWN_IDS: Int = 16

        /** A signing timestamp in 2026 (10 µs units since 2015-01-01). */
        public const val BASE_TIMESTAMP: Long = 37_600_000_000_000L
    }
}

/** Every message class of the codec's dialect (the codec keeps the list internal). */
internal fun MessageCodec.messageClassesForFuzzing(): List<Class<*>> = messageClasses
