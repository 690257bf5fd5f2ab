package pod.mavlink

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.longs.shouldBeInRange
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.runTest
import pod.core.vehicle.VehicleLost
import pod.mavlink.command.CommandTiming
import pod.mavlink.command.MavCommands
import pod.mavlink.command.ScriptedVehicle
import pod.mavlink.command.VehicleCommand
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.mission.MissionItem
import kotlin.time.Duration.Companion.seconds

/** A station and a [ScriptedVehicle] answering with [answer], on a perfect memory network in virtual time. */
private suspend fun TestScope.withScripted(answer: suspend (Any) -> List<Any>, block: suspend (MavlinkVehicle, ScriptedVehicle) -> Unit) {
    val timebase = virtualTimebase()
    val network = MemoryNetwork(backgroundScope, timebase)
    val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = timebase)
    val station = GroundStation.open(network.open("udpin://127.0.0.1:14550"), backgroundScope, config)
    val scripted = ScriptedVehicle.start(backgroundScope, network.open("udpout://127.0.0.1:14550"), answer = answer)
    block(station.vehicles.first { 1 in it }.getValue(1), scripted)
}

/** The one driver every protocol runs on (VehicleExchange.run): what it does around the machines. */
class ProtocolDriverTest : StringSpec({

    "a command to a vehicle that falls silent is shown as awaited while it is resent, and fails with VehicleLost once the vehicle is lost" {
        runTest {
            withScripted(answer = { emptyList() }) { vehicle, scripted ->
                val shown = backgroundScope.async { vehicle.awaiting.filterNotNull().first() }
                scripted.silence()
                val started = testScheduler.currentTime
                val error = shouldThrow<VehicleLost> { vehicle.commands.send(VehicleCommand(MavCommands.COMPONENT_ARM_DISARM, param1 = 1f)) }
                error.during shouldBe "MAV_CMD_COMPONENT_ARM_DISARM"
                // Lost after GroundStationConfig.lostAfter (3 s) of silence, long before the command's own 10 s.
                (testScheduler.currentTime - started) shouldBeInRange 2_000L..4_000L
                val awaited = shown.await()
                awaited.what shouldBe "MAV_CMD_COMPONENT_ARM_DISARM"
                awaited.giveUpAfter shouldBe CommandTiming().timeout
                vehicle.awaiting.value shouldBe null
            }
        }
    }

    "an upload cancelled by its caller tells the vehicle with MISSION_ACK OPERATION_CANCELLED" {
        runTest {
            val seen = ArrayList<Any>()
            withScripted(answer = { message ->
                seen += message
                emptyList() // never asks for an item: the upload waits until it is cancelled
            }) { vehicle, _ ->
                val upload = backgroundScope.async { vehicle.mission.upload(listOf(MissionItem(0, 3, 16, x = 1, y = 2, z = 10f))) }
                testScheduler.advanceTimeBy(1.seconds)
                upload.cancel()
                testScheduler.advanceTimeBy(1.seconds)
                val ack = seen.filterIsInstance<io.dronefleet.mavlink.common.MissionAck>().single()
                ack.type().value() shouldBe 15 // MAV_MISSION_OPERATION_CANCELLED
            }
        }
    }
})
