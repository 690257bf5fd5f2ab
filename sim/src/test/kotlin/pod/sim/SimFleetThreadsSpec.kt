package pod.sim

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.command.VehicleCommand
import kotlin.time.Duration.Companion.seconds

/**
 * A simulated fleet on real UDP sockets holds no thread per vehicle: its links share the
 * process's UDP receive threads (at most one per core), and every vehicle still hears its own
 * commands. About a second.
 */
class SimFleetThreadsSpec : StringSpec({

    "40 simulated vehicles share at most one receive thread per core, and each answers a command of its own" {
        coroutineScope {
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false))
            val fleet = SimFleet.start(40, this, SimVehicleConfig(systemId = 1, gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
            try {
                val vehicles = withTimeout(20.seconds) { gcs.vehicles.first { it.size >= 40 } }.values
                val receiveThreads = Thread.getAllStackTraces().keys.count { it.isAlive && it.name.startsWith("pod-udp-receive") }
                receiveThreads shouldBeLessThanOrEqual Runtime.getRuntime().availableProcessors()
                // SET_MESSAGE_INTERVAL (511) for HEARTBEAT at 1 Hz: each vehicle accepts (MAV_RESULT 0).
                val results = withTimeout(20.seconds) {
                    vehicles.map { v -> async { v.commands.send(VehicleCommand(command = 511, param1 = 1f, param2 = 1_000_000f)).resultCode } }.awaitAll()
                }
                results shouldBe List(40) { 0 }
            } finally {
                fleet.stop()
                gcs.closeAndAwait()
            }
        }
    }
})
