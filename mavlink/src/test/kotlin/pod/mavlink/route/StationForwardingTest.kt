package pod.mavlink.route

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.virtualTimebase
import kotlin.time.Duration.Companion.seconds

/** [GroundStation.forwardTo]: a Pod station serves its vehicle to another ground station on another port. */
class StationForwardingTest : StringSpec({

    "the station's vehicle reaches the other ground station, whose commands reach the vehicle unchanged; closing stops it" {
        runTest {
            val timebase = virtualTimebase()
            val network = MemoryNetwork(backgroundScope, timebase)
            val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = timebase)
            val gcs = GroundStation.open(network.open("udpin://127.0.0.1:14550"), backgroundScope, config)
            val vehicle = Node.toListening("vehicle", network, 14550, backgroundScope)
            val beating = backgroundScope.launch {
                var n = 0L
                while (true) {
                    vehicle.send(heartbeat(1, 1, n++))
                    delay(1.seconds)
                }
            }
            gcs.vehicles.first { 1 in it }
            val qgcSide = network.open("udpout://127.0.0.1:14600")
            val qgc = Node.listening("qgc", network, 14600, qgcSide, backgroundScope)
            val router = gcs.forwardTo(qgcSide)
            delay(2.5.seconds)
            qgc.receivedHex() shouldContainExactly listOf(heartbeat(1, 1, 1).hex(), heartbeat(1, 1, 2).hex())
            qgc.send(heartbeat(255, 191))
            qgc.send(command(255, 191, targetSys = 1, targetComp = 1, tag = 44))
            testScheduler.runCurrent()
            vehicle.receivedHex() shouldContain command(255, 191, 1, 1, 44).hex()
            // The vehicle's answer to QGC (255/191) goes there; the station hears it too and stays Pod's.
            qgc.received.clear()
            vehicle.send(command(1, 1, targetSys = 255, targetComp = 191, tag = 45))
            testScheduler.runCurrent()
            qgc.receivedHex() shouldContainExactly listOf(command(1, 1, 255, 191, 45).hex())
            router.stats().map { it.address } shouldBe listOf("udpin://127.0.0.1:14550", "udpout://127.0.0.1:14600")
            router.close()
            qgc.received.clear()
            delay(3.seconds)
            qgc.received.size shouldBe 0
            gcs.vehicles.value.getValue(1).connection.value shouldBe pod.core.vehicle.ConnectionState.CONNECTED
            beating.cancel()
        }
    }
})
