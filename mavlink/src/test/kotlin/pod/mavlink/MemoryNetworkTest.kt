package pod.mavlink

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.delay
import kotlinx.coroutines.test.runTest
import pod.core.vehicle.ConnectionState
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.link.PortInUse
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.seconds

class MemoryNetworkTest : StringSpec({
    fun heartbeat(sequence: Int) = copterHeartbeat(7, sequence)

    "a station on a memory network finds a vehicle, hears our heartbeat back, and loses it after lostAfter of virtual time" {
        runTest {
            val timebase = virtualTimebase()
            val network = MemoryNetwork(backgroundScope, timebase)
            val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = timebase)
            val gcs = GroundStation.open(network.open("udpin://127.0.0.1:14550"), backgroundScope, config)
            val vehicleLink = network.open("udpout://127.0.0.1:14550")
            var heardFromGcs = 0
            backgroundScope.launch { vehicleLink.receive { _, _ -> heardFromGcs++ } }
            val talking = backgroundScope.launch {
                var seq = 0
                while (true) {
                    vehicleLink.sendToAll(heartbeat(seq++))
                    delay(1.seconds)
                }
            }
            val found = gcs.vehicles.first { 7 in it }.getValue(7)
            found.connection.value shouldBe ConnectionState.CONNECTED
            delay(10.seconds)
            found.connection.value shouldBe ConnectionState.CONNECTED
            (heardFromGcs >= 9) shouldBe true
            talking.cancel()
            val silentAt = testScheduler.currentTime
            found.connection.first { it == ConnectionState.LOST }
            val lostAfterMs = testScheduler.currentTime - silentAt
            (lostAfterMs in 2_000..3_500) shouldBe true
            delay(1.hours)
            found.connection.value shouldBe ConnectionState.LOST
        }
    }

    "an address can be bound once" {
        runTest {
            val network = MemoryNetwork(backgroundScope, virtualTimebase())
            network.open("udpin://127.0.0.1:14550")
            shouldThrow<PortInUse> { network.open("udpin://127.0.0.1:14550") }
        }
    }
})
