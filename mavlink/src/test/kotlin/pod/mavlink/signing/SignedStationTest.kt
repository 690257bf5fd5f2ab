package pod.mavlink.signing

import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.tlog.FrameDirection
import pod.mavlink.tlog.FrameTap
import pod.mavlink.virtualTimebase
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

private val KEY = SigningKey(ByteArray(32) { (it * 13 + 5).toByte() })
private val OTHER_KEY = SigningKey(ByteArray(32) { (it * 13 + 6).toByte() })
private const val BOOT_MILLIS = SigningClock.EPOCH_2015_MILLIS + 360_000_000_000L
private const val ARMED = 128 // MAV_MODE_FLAG_SAFETY_ARMED

private fun heartbeat(systemId: Int, componentId: Int, armed: Boolean, sequence: Int): ByteArray = FrameEncoder().encode(
    Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
        .baseMode(EnumValue.create(if (armed) ARMED else 0)).systemStatus(MavState.MAV_STATE_STANDBY).mavlinkVersion(3).build(),
    systemId, componentId, sequence and 255,
)

private fun frameOf(bytes: ByteArray): MavFrame = buildList { FrameDecoder().feed(bytes) { add(it) } }.single()

/** [bytes] (a signed frame) with [change] applied to its decoded form and a good CRC again: what an attacker sends. */
private fun reencoded(bytes: ByteArray, change: (MavFrame) -> MavFrame): ByteArray = FrameEncoder().encode(change(frameOf(bytes)))

class SignedStationTest : StringSpec({

    "10,000 forged frames into a signed station: none accepted, none recorded, none acted on, each counted by kind" {
        runTest(timeout = 2.seconds * 60) {
            val timebase = virtualTimebase()
            val now = { BOOT_MILLIS + testScheduler.currentTime }
            val network = MemoryNetwork(backgroundScope, timebase)
            val config = GroundStationConfig(
                streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = timebase,
                signing = LinkSigning(KEY, linkId = 0, epochMillis = now),
            )
            val gcs = GroundStation.open(network.open("udpin://127.0.0.1:14550"), backgroundScope, config)
            val recorded = AtomicInteger()
            gcs.record(FrameTap { _, direction, _ -> if (direction == FrameDirection.RECEIVED) recorded.incrementAndGet() })
            val vehicle = network.open("udpout://127.0.0.1:14550")
            val attacker = network.open("udpout://127.0.0.1:14550")
            val genuine = SignedFrames(LinkSigning(KEY, linkId = 1, epochMillis = now), MessageCodec.Default)
            var genuineSent = 0
            suspend fun genuineHeartbeat(): ByteArray = genuine.sign(heartbeat(1, 1, armed = false, genuineSent)).also {
                vehicle.sendToAll(it)
                genuineSent++
            }
            val first = genuineHeartbeat()
            val found = withTimeout(5.seconds) { gcs.vehicles.first { 1 in it } }.getValue(1)
            delay(1.seconds)
            val recent = genuineHeartbeat()

            val wrongKey = SignedFrames(LinkSigning(OTHER_KEY, linkId = 1, epochMillis = now), MessageCodec.Default)
            val twoMinutesLate = SignedFrames(LinkSigning(KEY, linkId = 1, epochMillis = { now() - 120_000 }), MessageCodec.Default)
            val kinds = IntArray(7)
            repeat(10_000) { i ->
                val kind = i % 7
                kinds[kind]++
                val forged = when (kind) {
                    0 -> wrongKey.sign(heartbeat(1, 1, armed = true, i)) // wrong key
                    1 -> reencoded(recent) { f -> // altered payload: the armed flag set
                        MavFrame(2, f.sequence, f.systemId, f.componentId, f.messageId, f.payload.copyOf().also { it[4] = ARMED.toByte() }, signature = f.signature)
                    }
                    2 -> reencoded(recent) { f -> MavFrame(2, f.sequence, 66, f.componentId, f.messageId, f.payload, signature = f.signature) } // altered header
                    3 -> recent // replayed as it was
                    4 -> twoMinutesLate.sign(heartbeat(1, 2, armed = true, i)) // a new stream over a minute old
                    5 -> reencoded(recent) { f -> // another link id
                        MavFrame(2, f.sequence, f.systemId, f.componentId, f.messageId, f.payload, signature = f.signature!!.copyOf().also { it[0] = 7 })
                    }
                    else -> heartbeat(if (i % 2 == 0) 1 else 66, 1, armed = true, i) // unsigned
                }
                attacker.sendToAll(forged)
                if (i % 100 == 99) delay(10.milliseconds)
            }
            attacker.sendToAll(first) // and the very first genuine frame, replayed last
            genuineHeartbeat()
            withTimeout(5.seconds) { while (recorded.get() < genuineSent) delay(10.milliseconds) } // the genuine vehicle is still heard
            val stats = withTimeout(5.seconds) {
                gcs.stats.first { it.badSignatures + it.replayedFrames + it.unsignedRefused == 10_001L }
            }
            stats.badSignatures shouldBe (kinds[0] + kinds[1] + kinds[2] + kinds[5]).toLong()
            stats.replayedFrames shouldBe (kinds[3] + kinds[4] + 1).toLong()
            stats.unsignedRefused shouldBe kinds[6].toLong()
            gcs.vehicles.value.keys shouldBe setOf(1)
            found.telemetry.armed.value shouldBe false
            recorded.get() shouldBe genuineSent
            gcs.close()
        }
    }

    "a signed station signs every frame it sends, on its link id, and they verify with the key" {
        runTest {
            val timebase = virtualTimebase()
            val network = MemoryNetwork(backgroundScope, timebase)
            val config = GroundStationConfig(timebase = timebase, signing = LinkSigning(KEY, linkId = 5, epochMillis = { BOOT_MILLIS + testScheduler.currentTime }))
            val gcs = GroundStation.open(network.open("udpin://127.0.0.1:14551"), backgroundScope, config)
            val vehicle = network.open("udpout://127.0.0.1:14551")
            val heard = ArrayList<ByteArray>()
            backgroundScope.launch { vehicle.receive { _, bytes -> heard += bytes } }
            val signer = SignedFrames(LinkSigning(KEY, linkId = 1, epochMillis = { BOOT_MILLIS + testScheduler.currentTime }), MessageCodec.Default)
            repeat(5) { vehicle.sendToAll(signer.sign(heartbeat(1, 1, armed = false, it))); delay(1.seconds) }
            (heard.size >= 5) shouldBe true // heartbeats and the discovery requests
            for (bytes in heard) {
                FrameSignature.verify(bytes, KEY) shouldBe true
                FrameSignature.linkId(bytes) shouldBe 5
            }
            heard.map { FrameSignature.timestamp(it) }.zipWithNext().all { (a, b) -> b > a } shouldBe true
            gcs.close()
        }
    }
})
