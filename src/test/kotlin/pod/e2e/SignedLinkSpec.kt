package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.VehicleTiming
import pod.mavlink.codec.MessageCodec
import pod.mavlink.command.CommandTimeout
import pod.mavlink.command.CommandTiming
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import pod.mavlink.signing.FrameSignature
import pod.mavlink.signing.LinkSigning
import pod.mavlink.signing.SigningClock
import pod.mavlink.signing.SigningKey
import pod.mavlink.signing.setupMessage
import pod.mavlink.tlog.FrameDirection
import pod.mavlink.tlog.FrameTap
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration.Companion.seconds

private val KEY = SigningKey(ByteArray(32) { (it * 5 + 3).toByte() })
private val OTHER_KEY = SigningKey(ByteArray(32) { (it * 5 + 4).toByte() })
private val QUICK = VehicleTiming(commands = CommandTiming(timeout = 2.seconds))

/** A link whose every outgoing MAVLink 2 frame is signed with [key]: a station forging signatures. */
private class ForgingLink(private val inner: MavlinkLink, private val key: SigningKey) : MavlinkLink by inner {
    private var timestamp = SigningClock.fromEpochMillis(System.currentTimeMillis())
    private fun forged(bytes: ByteArray): ByteArray {
        val crcExtra = MessageCodec.Default.crcExtra(FrameSignature.messageId(bytes))
        return synchronized(this) { FrameSignature.signUnsigned(bytes, crcExtra, key, 0, timestamp++) }
    }
    override val sendsInPlace: Boolean get() = false
    override suspend fun send(bytes: ByteArray, peer: LinkPeer) = inner.send(forged(bytes), peer)
    override suspend fun sendToAll(bytes: ByteArray) = inner.sendToAll(forged(bytes))
}

/** Virtual time, one vehicle holding [KEY]. */
class SignedLinkSpec : StringSpec({

    "a signed arm is obeyed by a vehicle holding the key, and every frame it sends is signed" {
        virtualRun {
            flying(SimVehicleConfig(systemId = 61, signingKey = KEY), GroundStationConfig(signing = LinkSigning(KEY))) { v, sim ->
                Flights.keepArmedOnGround(v)
                v.action.arm()
                sim.state.value.armed shouldBe true
                v.telemetry.armed.value shouldBe true
                sim.refusedFrames shouldBe 0
            }
        }
    }

    "an unsigned arm is ignored: the vehicle stays disarmed and the command times out with CommandTimeout" {
        virtualRun {
            heard(SimVehicleConfig(systemId = 62, signingKey = KEY), GroundStationConfig(vehicleTiming = QUICK)) { v, sim ->
                shouldThrow<CommandTimeout> { v.action.arm() }.waitingFor shouldBe "COMMAND_ACK"
                sim.state.value.armed shouldBe false
                sim.refusedFrames shouldBeGreaterThan 0
            }
        }
    }

    "an arm signed with another key is ignored: the vehicle stays disarmed and the command times out" {
        virtualRun {
            signed(SimVehicleConfig(systemId = 63, signingKey = KEY), GroundStationConfig(vehicleTiming = QUICK), { ForgingLink(it, OTHER_KEY) }) { _, v, sim ->
                shouldThrow<CommandTimeout> { v.action.arm() }
                sim.state.value.armed shouldBe false
                sim.refusedFrames shouldBeGreaterThan 0
            }
        }
    }

    "a genuine signed arm replayed later is ignored" {
        virtualRun {
            signed(SimVehicleConfig(systemId = 64, signingKey = KEY), GroundStationConfig(signing = LinkSigning(KEY))) { gcs, v, sim ->
                Flights.vehicle(gcs, 64)
                val sent = CopyOnWriteArrayList<ByteArray>()
                Flights.keepArmedOnGround(v)
                val recording = gcs.record(FrameTap { _, direction, frame -> if (direction == FrameDirection.SENT) sent += frame })
                v.action.arm()
                recording.stop()
                v.action.disarm()
                sim.state.value.armed shouldBe false
                val refusedBefore = sim.refusedFrames
                val attacker = network.open("udpout://127.0.0.1:${sim.localPort}")
                for (frame in sent) attacker.sendToAll(frame)
                delay(3.seconds)
                sim.state.value.armed shouldBe false
                sim.refusedFrames shouldBeGreaterThan refusedBefore
            }
        }
    }

    "SETUP_SIGNING keys an unkeyed vehicle: then it ignores unsigned commands and obeys signed ones; refused while armed" {
        virtualRun {
            signed(SimVehicleConfig(systemId = 65), GroundStationConfig(signing = LinkSigning(KEY, acceptUnsigned = true))) { gcs, v, sim ->
                Flights.vehicle(gcs, 65)
                Flights.keepArmedOnGround(v)
                v.send(KEY.setupMessage(65, 1, SigningClock.fromEpochMillis(System.currentTimeMillis())))
                withTimeout(5.seconds) { v.messages.first { it.frame.signature != null } }
                v.action.arm()
                sim.state.value.armed shouldBe true
                // Armed, it keeps its key: "ERROR: Won't setup signing when armed".
                v.send(OTHER_KEY.setupMessage(65, 1, 0))
                withTimeout(5.seconds) { v.statusTexts.first { it.text == "ERROR: Won't setup signing when armed" } }
                v.action.disarm()
                sim.state.value.armed shouldBe false
            }
        }
        virtualRun {
            heard(SimVehicleConfig(systemId = 66), GroundStationConfig(vehicleTiming = QUICK)) { v, sim ->
                Flights.keepArmedOnGround(v)
                v.send(KEY.setupMessage(66, 1, SigningClock.fromEpochMillis(System.currentTimeMillis())))
                withTimeout(5.seconds) { v.messages.first { it.frame.signature != null } }
                shouldThrow<CommandTimeout> { v.action.arm() }
                sim.state.value.armed shouldBe false
            }
        }
    }
})

/**
 * A station of [station] (on a link made by [wrap] from a fresh memory link) and a vehicle of
 * [config] sending to it; [block] once the station heard the vehicle; both stop afterwards.
 */
private suspend fun VirtualFleet.signed(
    config: SimVehicleConfig,
    station: GroundStationConfig,
    wrap: (MavlinkLink) -> MavlinkLink = { it },
    block: suspend CoroutineScope.(GroundStation, MavlinkVehicle, SimVehicle) -> Unit,
) = coroutineScope {
    val gcs = GroundStation.open(wrap(network.open("udpin://127.0.0.1:0")), this, station.copy(timebase = timebase))
    val sim = vehicle(config, gcs)
    try {
        sim.start(this)
        block(gcs, withTimeout(10.seconds) { gcs.vehicles.first { config.systemId in it } }.getValue(config.systemId), sim)
    } finally {
        sim.stop()
        gcs.close()
    }
}
