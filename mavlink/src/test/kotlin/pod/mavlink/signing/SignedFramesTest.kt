package pod.mavlink.signing

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.byte
import io.kotest.property.arbitrary.byteArray
import io.kotest.property.arbitrary.constant
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec

private val KEY = SigningKey(ByteArray(32) { (it * 7 + 1).toByte() })
private const val START_MILLIS = SigningClock.EPOCH_2015_MILLIS + 300_000_000_000L

/** A HEARTBEAT-shaped unsigned frame (message 0, 9 payload bytes) from [sys]/[comp]. */
private fun unsigned(sys: Int, comp: Int, seq: Int, payload: ByteArray) =
    FrameEncoder().encode(MavFrame(2, seq, sys, comp, 0, payload))

private fun decoded(bytes: ByteArray): List<MavFrame> = buildList { FrameDecoder().feed(bytes) { add(it) } }

private fun signer(linkId: Int = 3, key: SigningKey = KEY) =
    SignedFrames(LinkSigning(key, linkId, allowUnsigned = UnsignedFilter.NONE, epochMillis = { START_MILLIS }), MessageCodec.Default)

class SignedFramesTest : StringSpec({

    "signing round trip: any frame a signer signs is admitted once by a receiver with the same key, then refused as a replay" {
        val sender = signer()
        val receiver = signer(linkId = 9)
        checkAll(500, Arb.int(1..255), Arb.int(0..255), Arb.int(0..255), Arb.byteArray(Arb.constant(9), Arb.byte())) { sys, comp, seq, payload ->
            val signed = sender.sign(unsigned(sys, comp, seq, payload))
            FrameSignature.isSigned(signed) shouldBe true
            FrameSignature.linkId(signed) shouldBe 3
            val frames = decoded(signed)
            frames.size shouldBe 1
            receiver.admit(frames[0]) shouldBe true
            receiver.admit(decoded(signed)[0]) shouldBe false
        }
        receiver.badSignatures shouldBe 0
        receiver.replayed shouldBe 500
    }

    "an altered signed frame is never admitted, whatever byte changes, even with its CRC made good again" {
        val sender = signer()
        checkAll(1_000, Arb.int(0..35), Arb.int(1..255), Arb.byteArray(Arb.constant(9), Arb.byte())) { at, flip, payload ->
            val signed = sender.sign(unsigned(1, 1, 0, payload))
            val receiver = signer()
            // As it arrives with one byte changed (the decoder drops most for their CRC) ...
            val wire = signed.copyOf().also { it[at % it.size] = (it[at % it.size].toInt() xor flip).toByte() }
            for (frame in decoded(wire)) receiver.admit(frame) shouldBe false
            // ... and altered field by field with a good CRC, as an attacker would send it.
            val refusedBefore = receiver.badSignatures
            val f = decoded(signed)[0]
            val sig = f.signature!!
            val altered = when (at % 6) {
                0 -> MavFrame(2, f.sequence, f.systemId, f.componentId, f.messageId, f.payload.copyOf().also { it[at % 9] = (it[at % 9].toInt() xor flip).toByte() }, signature = sig)
                1 -> MavFrame(2, f.sequence, f.systemId xor flip, f.componentId, f.messageId, f.payload, signature = sig)
                2 -> MavFrame(2, f.sequence, f.systemId, f.componentId xor flip, f.messageId, f.payload, signature = sig)
                3 -> MavFrame(2, f.sequence xor flip, f.systemId, f.componentId, f.messageId, f.payload, signature = sig)
                4 -> MavFrame(2, f.sequence, f.systemId, f.componentId, f.messageId, f.payload, compatFlags = flip, signature = sig)
                else -> MavFrame(2, f.sequence, f.systemId, f.componentId, f.messageId, f.payload, signature = sig.copyOf().also { it[at % 13] = (it[at % 13].toInt() xor flip).toByte() })
            }
            for (frame in decoded(FrameEncoder().encode(altered))) receiver.admit(frame) shouldBe false
            receiver.badSignatures shouldBe refusedBefore + 1
        }
    }

    "a frame signed with another key or moved to another link id fails; unsigned frames follow the filter" {
        val wrongKey = signer(key = SigningKey(ByteArray(32) { 9 }))
        val receiver = SignedFrames(LinkSigning(KEY, epochMillis = { START_MILLIS }), MessageCodec.Default)
        receiver.admit(decoded(wrongKey.sign(unsigned(1, 1, 0, ByteArray(9) { 1 })))[0]) shouldBe false
        val moved = signer().sign(unsigned(1, 1, 1, ByteArray(9) { 1 }))
        moved[moved.size - 13] = 4
        receiver.admit(decoded(moved)[0]) shouldBe false
        receiver.badSignatures shouldBe 2
        val radioStatus = FrameEncoder().encode(MavFrame(2, 0, 51, 68, UnsignedFilter.RADIO_STATUS, ByteArray(9) { 1 }))
        receiver.admit(decoded(radioStatus)[0]) shouldBe true
        receiver.admit(decoded(unsigned(1, 1, 2, ByteArray(9) { 1 }))[0]) shouldBe false
        receiver.unsignedAccepted shouldBe 1
        receiver.unsignedRefused shouldBe 1
    }

    "a verified frame from a clock running ahead moves our own clock forward" {
        var peerMillis = START_MILLIS + 3_600_000
        val ahead = SignedFrames(LinkSigning(KEY, epochMillis = { peerMillis }), MessageCodec.Default)
        val we = signer()
        we.admit(decoded(ahead.sign(unsigned(1, 1, 0, ByteArray(9))))[0]) shouldBe true
        val ours = we.sign(unsigned(255, 190, 0, ByteArray(9)))
        (FrameSignature.timestamp(ours) > SigningClock.fromEpochMillis(START_MILLIS + 3_600_000)) shouldBe true
    }
})
