package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filter
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.take
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.CommandResult
import pod.mavlink.command.VehicleCommand
import kotlin.time.Duration.Companion.seconds

private const val SYSID = 23

/**
 * Runs [block] with a Pod ground station listening on loopback and pymavlink_command_vehicle.py
 * (a foreign MAVLink encoder answering commands with scripted COMMAND_ACK sequences) sending to it.
 * [block] runs in the scope of the ground station.
 */
private suspend fun withScriptedVehicle(block: suspend CoroutineScope.(MavlinkVehicle, JsonPeer) -> Unit) = coroutineScope {
    val gcs = GroundStation.open("udpin://127.0.0.1:0", this)
    val peer = Python.startJson("pymavlink_command_vehicle.py", gcs.link.localPort, SYSID, 30)
    try {
        withTimeout(15.seconds) { peer.await("ready") }
        val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { SYSID in it } }.getValue(SYSID)
        withTimeout(20.seconds) { block(vehicle, peer) }
    } finally {
        peer.stop()
        gcs.close()
    }
}

/** The [count] first events of this peer named [name] with "command" [command]. */
private suspend fun JsonPeer.events(name: String, command: Int, count: Int): List<Map<String, String>> =
    withTimeout(5.seconds) { events.filter { it["event"] == name && it["command"] == "$command" }.take(count).toList() }

/** Pod's CommandService against COMMAND_ACKs encoded by pymavlink, not by Pod's own codec. */
class PymavlinkCommandSpec : StringSpec({

    "IN_PROGRESS acks with progress from pymavlink come as a flow, and its last element's ACCEPTED carries result_param2" {
        withScriptedVehicle { vehicle, peer ->
            val progress = vehicle.commands.sending(VehicleCommand(241, param1 = 1f)).toList()
            val reply = progress.last().reply!!
            reply.result shouldBe CommandResult.ACCEPTED
            reply.resultParam2 shouldBe 7
            progress.dropLast(1).map { it.percent } shouldBe listOf(10, 60)
            // Sent once: an IN_PROGRESS answer stops the resends.
            peer.events("command", 241, 1).single()["confirmation"] shouldBe "0"
        }
    }

    "TEMPORARILY_REJECTED twice, then ACCEPTED: Pod resends with confirmation 1 and 2 and returns the acceptance" {
        withScriptedVehicle { vehicle, peer ->
            vehicle.commands.send(VehicleCommand(400, param1 = 1f)).result shouldBe CommandResult.ACCEPTED
            peer.events("command", 400, 3).map { it["confirmation"] } shouldBe listOf("0", "1", "2")
            peer.events("ack", 400, 3).map { it["result"] } shouldBe listOf("1", "1", "0")
        }
    }

    "acks addressed to another system or sent by another component are not taken for the answer; the refusal carries the vehicle's warning" {
        withScriptedVehicle { vehicle, peer ->
            // MavlinkVehicle.statusTexts does not replay: listen before sending.
            val texts = async(start = CoroutineStart.UNDISPATCHED) { vehicle.statusTexts.take(2).toList() }
            val error = shouldThrow<CommandRejected> { vehicle.commands.send(VehicleCommand(178, param1 = 1f, param2 = 12f)) }
            error.result shouldBe CommandResult.DENIED
            error.attempts shouldBe 1
            // pymavlink's STATUSTEXT (MAVLink 2, id and chunk_seq truncated away): NOTICE is chatter, WARNING explains.
            error.statusTexts shouldBe listOf("Speed 12 m/s above limit")
            withTimeout(2.seconds) { texts.await() }.map { it.text } shouldBe listOf("Speed change requested", "Speed 12 m/s above limit")
            peer.events("ack", 178, 3).map { it["target_system"] + "/" + it["from_component"] + "/" + it["result"] } shouldBe
                listOf("99/1/0", "255/154/0", "255/1/2")
        }
    }

    "MAVLink 1 acks with and without extension bytes, and a MAVLink 2 ack truncated to one payload byte, all read as ACCEPTED" {
        withScriptedVehicle { vehicle, peer ->
            vehicle.commands.send(VehicleCommand(20)).result shouldBe CommandResult.ACCEPTED
            val v10 = peer.events("ack", 20, 1).single()
            v10["magic"] shouldBe "254"
            v10["payload_len"] shouldBe "3"
            // pymavlink's force_mavlink1 keeps the extension fields in a MAVLink 1 frame.
            vehicle.commands.send(VehicleCommand(17)).result shouldBe CommandResult.ACCEPTED
            val v1 = peer.events("ack", 17, 1).single()
            v1["magic"] shouldBe "254"
            v1["payload_len"] shouldBe "10"

            val reply = vehicle.commands.send(VehicleCommand(21, param4 = Float.NaN))
            // The bytes MAVLink 2 dropped read as zero.
            reply.result shouldBe CommandResult.ACCEPTED
            reply.progress shouldBe 0
            reply.resultParam2 shouldBe 0
            val truncated = peer.events("ack", 21, 1).single()
            truncated["magic"] shouldBe "253"
            truncated["target_system"] shouldBe "0"
            // Only the low byte of the command (21) is left: MAVLink 2 drops every trailing zero.
            truncated["payload_len"] shouldBe "1"
        }
    }

    "a COMMAND_INT in a global frame reaches pymavlink with latitude and longitude as exact degrees × 10⁷" {
        withScriptedVehicle { vehicle, peer ->
            vehicle.commands.send(VehicleCommand(192, param1 = -1f, param2 = 1f, param5 = 41.1780461, param6 = -8.5957861, param7 = 135.25f, frame = 6))
                .result shouldBe CommandResult.ACCEPTED
            val received = peer.events("command", 192, 1).single()
            received["kind"] shouldBe "int"
            received["frame"] shouldBe "6"
            received["x"] shouldBe "411780461"
            received["y"] shouldBe "-85957861"
            received["z"] shouldBe "135.25"
        }
    }
})
