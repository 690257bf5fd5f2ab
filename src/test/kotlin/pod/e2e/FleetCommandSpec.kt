package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.mavlink.command.CommandResult
import pod.mavlink.command.VehicleCommand
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * Commands to many vehicles at once, in virtual time on a memory network: bounds are vehicle time.
 * What a real socket adds with many peers on one port (source addresses, the receive thread) stays
 * on loopback UDP: FleetDiscoverySpec's first test, and the command round-trip benchmark's 100
 * vehicles (BENCHMARKS.md).
 */
class FleetCommandSpec : StringSpec({

    "100 simulated vehicles in one process each accept a command sent to all of them at once, three rounds running" {
        // Loopback-like latency each way, drawn per datagram from the seed, so the hundred
        // transactions overlap in vehicle time and their answers arrive interleaved.
        virtualRun(up = LATENCY, down = LATENCY) {
            coroutineScope {
                val gcs = station(this)
                val fleet = fleet(this, 100, SimVehicleConfig(systemId = 101), gcs)
                try {
                    val vehicles = withTimeout(20.seconds) { gcs.vehicles.first { it.size == 100 } }.values.sortedBy { it.systemId }
                    repeat(3) {
                        // SET_MESSAGE_INTERVAL: SYS_STATUS at the 1 Hz it streams anyway.
                        val replies = withTimeout(30.seconds) {
                            vehicles.map { v -> async { v.commands.send(VehicleCommand(511, param1 = 1f, param2 = 1_000_000f)) } }.awaitAll()
                        }
                        replies.map { it.result }.toSet() shouldBe setOf(CommandResult.ACCEPTED)
                    }
                    fleet.vehicles.all { it.isRunning } shouldBe true
                } finally {
                    fleet.stop()
                    gcs.close()
                }
            }
        }
    }
})

private val LATENCY = LinkFaults(delay = 1.milliseconds, jitter = 2.milliseconds)
