package pod.bench

import io.dronefleet.mavlink.MavlinkConnection
import io.dronefleet.mavlink.serialization.payload.reflection.ReflectionPayloadDeserializer
import org.openjdk.jmh.annotations.Benchmark
import org.openjdk.jmh.annotations.BenchmarkMode
import org.openjdk.jmh.annotations.Mode
import org.openjdk.jmh.annotations.OutputTimeUnit
import org.openjdk.jmh.annotations.Param
import org.openjdk.jmh.annotations.Scope
import org.openjdk.jmh.annotations.Setup
import org.openjdk.jmh.annotations.State
import org.openjdk.jmh.infra.Blackhole
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec
import java.io.InputStream
import java.io.OutputStream
import java.util.concurrent.TimeUnit

// JMH subclasses @State classes and writes @Param fields from generated code in another package:
// the classes are `open` and the parameters public `@JvmField`s.
//
// Every benchmark decodes one frame per operation and hands the decoded object to a Blackhole, so
// the work cannot be dropped as dead code; the input bytes live in fields of the state object,
// which the JIT cannot treat as constants. Each state checks in @Setup that its decoder returns the
// very message the fixture was built from, so a fast but wrong decoder fails instead of scoring.

/**
 * Pod's receive path for one datagram: [FrameDecoder.feed] (frame sync, header, CRC_EXTRA) and
 * [MessageCodec.decode] of the frame it delivers, as the ground station runs them per datagram.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
open class PodDecodeBenchmark {
    @Param("HEARTBEAT", "SYS_STATUS", "ATTITUDE", "GLOBAL_POSITION_INT", "MISSION_CURRENT")
    @JvmField
    var message: String = ""

    private lateinit var datagram: ByteArray
    private lateinit var decoder: FrameDecoder
    private val codec = MessageCodec.Default

    // The sink is built once: a lambda created per call would add an allocation Pod does not make.
    private var decoded: Any? = null
    private val sink: (MavFrame) -> Unit = { frame -> decoded = codec.decode(frame) }

    @Setup
    fun setup() {
        val sample = Fixtures.Sample.valueOf(message)
        datagram = sample.datagram()
        decoder = FrameDecoder(codec)
        decoded = null
        decoder.feed(datagram, 0, datagram.size, sink)
        check(decoded == sample.message()) { "Pod decoded $message as $decoded, expected ${sample.message()}" }
    }

    @Benchmark
    fun feedAndDecode(blackhole: Blackhole) {
        decoder.feed(datagram, 0, datagram.size, sink)
        blackhole.consume(decoded)
    }
}

/**
 * Payload decoding alone, from the payload bytes of an already framed message: Pod's planned
 * [MessageCodec.decode] beside io.dronefleet's [ReflectionPayloadDeserializer] on the same bytes.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
open class PayloadDecodeBenchmark {
    @Param("HEARTBEAT", "GLOBAL_POSITION_INT")
    @JvmField
    var message: String = ""

    private lateinit var payload: ByteArray
    private lateinit var messageClass: Class<*>
    private lateinit var frame: MavFrame
    private val codec = MessageCodec.Default
    private val reflective = ReflectionPayloadDeserializer()

    @Setup
    fun setup() {
        val sample = Fixtures.Sample.valueOf(message)
        val expected = sample.message()
        val datagram = sample.datagram()
        payload = Fixtures.payloadOf(datagram)
        messageClass = expected.javaClass
        frame = MavFrame(
            version = 2,
            sequence = 0,
            systemId = Fixtures.SYSTEM_ID,
            componentId = Fixtures.COMPONENT_ID,
            messageId = messageIdOf(datagram),
            payload = payload,
        )
        val fromReflection = reflective.deserialize(payload, messageClass)
        check(fromReflection == expected) { "io.dronefleet decoded $message as $fromReflection, expected $expected" }
        val fromPod = codec.decode(frame)
        check(fromPod == expected) { "Pod decoded $message as $fromPod, expected $expected" }
    }

    @Benchmark
    fun podCodec(blackhole: Blackhole) {
        blackhole.consume(codec.decode(frame))
    }

    @Benchmark
    fun dronefleetReflective(blackhole: Blackhole) {
        blackhole.consume(reflective.deserialize(payload, messageClass))
    }

    private fun messageIdOf(datagram: ByteArray): Int =
        (datagram[7].toInt() and 0xFF) or ((datagram[8].toInt() and 0xFF) shl 8) or ((datagram[9].toInt() and 0xFF) shl 16)
}

/**
 * What an io.dronefleet user gets per frame: [MavlinkConnection.next] reading a stream that repeats
 * the datagram (packet reader, CRC_EXTRA check, dialect lookup, reflective payload decoding).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
open class DronefleetStreamBenchmark {
    @Param("HEARTBEAT", "GLOBAL_POSITION_INT")
    @JvmField
    var message: String = ""

    private lateinit var connection: MavlinkConnection

    @Setup
    fun setup() {
        val sample = Fixtures.Sample.valueOf(message)
        connection = MavlinkConnection.create(RepeatingInputStream(sample.datagram()), OutputStream.nullOutputStream())
        val first = connection.next().payload
        check(first == sample.message()) { "io.dronefleet decoded $message as $first, expected ${sample.message()}" }
    }

    @Benchmark
    fun connectionNext(blackhole: Blackhole) {
        blackhole.consume(connection.next())
    }
}

/** An endless stream of the same [bytes] over and over: a link that keeps sending one frame. */
private class RepeatingInputStream(private val bytes: ByteArray) : InputStream() {
    private var position = 0

    override fun read(): Int {
        val value = bytes[position].toInt() and 0xFF
        position = if (position + 1 == bytes.size) 0 else position + 1
        return value
    }

    override fun read(target: ByteArray, offset: Int, length: Int): Int {
        if (length == 0) return 0
        // Hand out at most the rest of the current copy, as a socket stream returns what it has.
        val count = minOf(length, bytes.size - position)
        System.arraycopy(bytes, position, target, offset, count)
        position = (position + count) % bytes.size
        return count
    }

    override fun available(): Int = bytes.size - position
}
