package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.VehicleTiming
import pod.mavlink.command.CommandResult
import pod.mavlink.command.CommandTimeout
import pod.mavlink.command.CommandTiming
import pod.mavlink.command.VehicleCommand
import pod.mavlink.signing.LinkSigning
import pod.mavlink.signing.SigningKey
import kotlin.time.Duration.Companion.seconds

private const val SIGNED_SYSID = 24
private const val KEY_HEX = "a1b2c3d4e5f60718293a4b5c6d7e8f90112233445566778899aabbccddeeff00"

/** Pod on loopback UDP with pymavlink_signed_vehicle.py (pymavlink's own signing) sending to it. */
private suspend fun withSignedPymavlink(config: GroundStationConfig, block: suspend CoroutineScope.(MavlinkVehicle, JsonPeer, GroundStation) -> Unit) = coroutineScope {
    val gcs = GroundStation.open("udpin://127.0.0.1:0", this, config)
    val peer = Python.startJson("pymavlink_signed_vehicle.py", gcs.link.localPort, SIGNED_SYSID, KEY_HEX, 30)
    try {
        withTimeout(15.seconds) { peer.await("ready") }
        val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { SIGNED_SYSID in it } }.getValue(SIGNED_SYSID)
        withTimeout(20.seconds) { block(vehicle, peer, gcs) }
    } finally {
        peer.stop()
        gcs.close()
    }
}

/** MAVLink 2 signing both ways between Pod and pymavlink with the same key. */
class PymavlinkSigningSpec : StringSpec({

    "a signed Pod arms a signed pymavlink vehicle: pymavlink verifies Pod's frames, Pod verifies pymavlink's" {
        withSignedPymavlink(GroundStationConfig(requestHome = false, requestPayloads = false, signing = LinkSigning(SigningKey.fromHex(KEY_HEX), linkId = 1))) { vehicle, peer, gcs ->
            vehicle.commands.send(VehicleCommand(400, param1 = 1f)).result shouldBe CommandResult.ACCEPTED
            vehicle.telemetry.armed.first { it }
            peer.await("command") { it["command"] == "400" }["signed"] shouldBe "true"
            val stats = peer.await("stats") { it["goodsig"]!!.toInt() >= 3 }
            stats["badsig"] shouldBe "0"
            stats["reject"] shouldBe "0"
            gcs.stats.first { it.frames >= 3 }.let { listOf(it.badSignatures, it.replayedFrames, it.unsignedRefused) } shouldBe listOf(0L, 0L, 0L)
        }
    }

    "pymavlink refuses an unsigned Pod's command, which times out; a Pod with another key hears nothing" {
        val quick = VehicleTiming(commands = CommandTiming(timeout = 2.seconds))
        withSignedPymavlink(GroundStationConfig(requestHome = false, requestPayloads = false, vehicleTiming = quick)) { vehicle, peer, _ ->
            shouldThrow<CommandTimeout> { vehicle.commands.send(VehicleCommand(400, param1 = 1f)) }
            vehicle.telemetry.armed.value shouldBe false
            peer.await("stats") { it["reject"]!!.toInt() >= 1 }["goodsig"] shouldBe "0"
        }
        coroutineScope {
            val other = SigningKey(ByteArray(32) { 1 })
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(signing = LinkSigning(other)))
            val peer = Python.startJson("pymavlink_signed_vehicle.py", gcs.link.localPort, SIGNED_SYSID, KEY_HEX, 30)
            try {
                withTimeout(15.seconds) { peer.await("ready") }
                withTimeout(10.seconds) { gcs.stats.first { it.badSignatures >= 2 } }
                gcs.vehicles.value.isEmpty() shouldBe true
            } finally {
                peer.stop()
                gcs.close()
            }
        }
    }
})
