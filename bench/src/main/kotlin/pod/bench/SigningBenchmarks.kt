package pod.bench

import org.openjdk.jmh.annotations.Benchmark
import org.openjdk.jmh.annotations.BenchmarkMode
import org.openjdk.jmh.annotations.Mode
import org.openjdk.jmh.annotations.OutputTimeUnit
import org.openjdk.jmh.annotations.Param
import org.openjdk.jmh.annotations.Scope
import org.openjdk.jmh.annotations.Setup
import org.openjdk.jmh.annotations.State
import org.openjdk.jmh.infra.Blackhole
import pod.mavlink.codec.MessageCodec
import pod.mavlink.signing.FrameSignature
import pod.mavlink.signing.ReplayGuard
import pod.mavlink.signing.SigningKey
import java.util.concurrent.TimeUnit

/**
 * What MAVLink 2 signing costs per frame: [sign] is what a signed station adds to each frame it
 * sends (signed flag, CRC again, SHA-256 over key and frame, the 13-byte block), [verify] what it
 * adds to each signed frame it receives before routing (SHA-256 and a constant-time compare, then
 * the replay check). Each state checks in @Setup that a signed frame verifies, and a frame signed
 * with another key does not, so a fast but wrong path fails instead of scoring.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
open class SigningBenchmark {
    @Param("HEARTBEAT", "GLOBAL_POSITION_INT")
    @JvmField
    var message: String = ""

    private val key = SigningKey(ByteArray(32) { (it * 3 + 1).toByte() })
    private lateinit var unsigned: ByteArray
    private lateinit var signed: ByteArray
    private var crcExtra = 0
    private var timestamp = 1_000_000_000L
    private val guard = ReplayGuard()

    @Setup
    fun setup() {
        unsigned = Fixtures.Sample.valueOf(message).datagram()
        crcExtra = MessageCodec.Default.crcExtra(FrameSignature.messageId(unsigned))
        signed = FrameSignature.signUnsigned(unsigned, crcExtra, key, 1, timestamp)
        check(FrameSignature.verify(signed, key)) { "a signed $message does not verify" }
        check(!FrameSignature.verify(signed, SigningKey(ByteArray(32)))) { "a signed $message verifies under another key" }
    }

    @Benchmark
    fun sign(): ByteArray = FrameSignature.signUnsigned(unsigned, crcExtra, key, 1, ++timestamp)

    @Benchmark
    fun verify(blackhole: Blackhole) {
        blackhole.consume(FrameSignature.verify(signed, key))
        // The replay check with a fresh timestamp each time, as for a stream's next frame.
        blackhole.consume(guard.accept(1, 1, 1, ++timestamp, timestamp))
    }
}
