package pod.mavlink.command

import io.dronefleet.mavlink.common.CommandLong
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.longs.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.runTest
import pod.mavlink.virtualTimebase
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.mission.Faults
import pod.mavlink.mission.SeededConditions
import pod.mavlink.link.MemoryNetwork
import kotlin.random.Random
import kotlin.time.Duration.Companion.hours

/**
 * The real [CommandService] of a real [GroundStation] against a vehicle that accepts every
 * command, on a seeded [MemoryNetwork] losing 30 % each way, in virtual time.
 */
class CommandLossPropertyTest : StringSpec({

    "over a link losing 30 % each way, 1000 seeded commands to an answering vehicle are all accepted within the timeout" {
        val timing = CommandTiming()
        for (seed in 1L..10L) {
            runTest {
                val timebase = virtualTimebase()
                val faults = Faults(drop = 0.3, minDelayMs = 5, maxDelayMs = 5)
                val network = MemoryNetwork(backgroundScope, timebase) { from, _ -> SeededConditions(faults, Random(seed * 1000 + from.port)) }
                val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, lostAfter = 24.hours, timebase = timebase)
                val station = GroundStation.open(network.open("udpin://127.0.0.1:14550"), backgroundScope, config)
                // Its heartbeats (every 100 ms) keep coming through the loss: the vehicle is heard talking.
                ScriptedVehicle.start(backgroundScope, network.open("udpout://127.0.0.1:14550")) { message ->
                    if (message is CommandLong) listOf(CommandWire.ack(message.command().value(), CommandResult.ACCEPTED, 255, 190, null)) else emptyList()
                }
                val vehicle = station.vehicles.first { 1 in it }.getValue(1)
                repeat(100) { n ->
                    val started = testScheduler.currentTime
                    val reply = vehicle.commands.send(VehicleCommand(MavCommands.COMPONENT_ARM_DISARM, param1 = (n % 2).toFloat()))
                    withClue("seed $seed, command $n") {
                        reply.result shouldBe CommandResult.ACCEPTED
                        testScheduler.currentTime - started shouldBeLessThanOrEqual timing.timeout.inWholeMilliseconds
                    }
                }
            }
        }
    }
})
