package pod.mavlink.signing

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldNotContain
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame

private fun hex(s: String) = ByteArray(s.length / 2) { s.substring(it * 2, it * 2 + 2).toInt(16).toByte() }
private fun ByteArray.hex() = joinToString("") { "%02x".format(it) }

/**
 * A HEARTBEAT (type 2, autopilot 3, base mode 0, custom mode 0, status 4, version 3) from system 1
 * component 1, sequence 0, signed with the key 00 01 … 1f on link 7 at timestamp 0x0123456789AB,
 * as pymavlink 2.4 packs it (`MAVLink.signing`, sign_outgoing): the reference vector.
 */
private const val PYMAVLINK_SIGNED_HEARTBEAT = "fd090100000101000000000000000203000403ad2f07ab8967452301a30954a15450"
private val KEY = SigningKey(ByteArray(32) { it.toByte() })

class FrameSignatureTest : StringSpec({

    "a frame encoded with a signature block and signed is byte for byte pymavlink's signed frame" {
        val payload = hex("000000000203000403")
        val frame = FrameEncoder().encode(MavFrame(2, 0, 1, 1, 0, payload, signature = ByteArray(13)))
        FrameSignature.sign(frame, KEY, linkId = 7, timestamp = 0x0123456789ABL).hex() shouldBe PYMAVLINK_SIGNED_HEARTBEAT
    }

    "pymavlink's signed frame verifies, with its link id and timestamp read back" {
        val frame = hex(PYMAVLINK_SIGNED_HEARTBEAT)
        FrameSignature.verify(frame, KEY) shouldBe true
        FrameSignature.linkId(frame) shouldBe 7
        FrameSignature.timestamp(frame) shouldBe 0x0123456789ABL
    }

    "a changed payload byte, link id, timestamp or key fails verification" {
        for (at in listOf(12, 21, 22, 27, 28)) {
            val frame = hex(PYMAVLINK_SIGNED_HEARTBEAT)
            frame[at] = (frame[at].toInt() xor 0x01).toByte()
            FrameSignature.verify(frame, KEY) shouldBe false
        }
        FrameSignature.verify(hex(PYMAVLINK_SIGNED_HEARTBEAT), SigningKey(ByteArray(32))) shouldBe false
    }

    "unsigned, truncated or MAVLink 1 frames are not signed frames: verify says false, sign refuses" {
        val unsigned = FrameEncoder().encode(MavFrame(2, 0, 1, 1, 0, hex("000000000203000403")))
        FrameSignature.isSigned(unsigned) shouldBe false
        FrameSignature.verify(unsigned, KEY) shouldBe false
        FrameSignature.verify(hex(PYMAVLINK_SIGNED_HEARTBEAT).copyOf(30), KEY) shouldBe false
        shouldThrow<IllegalArgumentException> { FrameSignature.sign(unsigned, KEY, 0, 1) }
        shouldThrow<IllegalArgumentException> { FrameSignature.sign(hex(PYMAVLINK_SIGNED_HEARTBEAT), KEY, 256, 1) }
        shouldThrow<IllegalArgumentException> { FrameSignature.sign(hex(PYMAVLINK_SIGNED_HEARTBEAT), KEY, 0, 1L shl 48) }
    }

    "a key is 32 bytes, reads from hex, and never prints its bytes" {
        SigningKey.fromHex("000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f") shouldBe KEY
        KEY.toString() shouldNotContain "0001"
        shouldThrow<IllegalArgumentException> { SigningKey(ByteArray(31)) }
        shouldThrow<IllegalArgumentException> { SigningKey.fromHex("00zz") }
    }

    "replays: a stream's timestamps must grow; a new stream may start at most a minute behind" {
        val guard = ReplayGuard()
        val now = 10_000_000L
        guard.accept(1, 1, 0, now - 100, now) shouldBe true
        guard.accept(1, 1, 0, now - 100, now) shouldBe false
        guard.accept(1, 1, 0, now - 50, now) shouldBe true
        guard.accept(1, 1, 0, now - 60, now) shouldBe false
        guard.accept(1, 1, 1, now - 60, now) shouldBe true // another link id is another stream
        guard.accept(2, 1, 0, now - ReplayGuard.NEW_STREAM_WINDOW - 1, now) shouldBe false
        guard.accept(2, 1, 0, now - ReplayGuard.NEW_STREAM_WINDOW, now) shouldBe true
    }

    "the signing clock counts 10 µs since 2015 and grows by at least one per frame" {
        var millis = SigningClock.EPOCH_2015_MILLIS + 1_000
        val clock = SigningClock { millis }
        clock.next() shouldBe 100_000L
        clock.next() shouldBe 100_001L
        millis -= 500 // the wall clock stepped back
        clock.next() shouldBe 100_002L
        millis += 10_000
        clock.next() shouldBe 1_050_000L
    }
})
