package pod.sim

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.runTest
import pod.core.time.Timebase
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.MemoryNetwork
import kotlin.time.Duration.Companion.minutes

/** `pod sim --out A --out B`: each vehicle reaches every output and answers whichever station asks. */
class FanOutOpenerTest : StringSpec({
    "two vehicles with two outputs: both stations find both, and each station's parameter read is answered" {
        runTest(timeout = 1.minutes) {
            val timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
            val network = MemoryNetwork(backgroundScope, timebase)
            val config = GroundStationConfig(timebase = timebase)
            val a = GroundStation.open(network.open("udpin://127.0.0.1:14550"), backgroundScope, config)
            val b = GroundStation.open(network.open("udpin://127.0.0.1:14551"), backgroundScope, config)
            val outputs = listOf(LinkAddress.parse("udpout:127.0.0.1:14550"), LinkAddress.parse("udpout:127.0.0.1:14551"))
            SimFleet.start(
                2, backgroundScope, SimVehicleConfig(systemId = 1, gcs = outputs.first().toString()),
                timebase = timebase, openLink = FanOutOpener(outputs, LinkOpener.memory(network)),
            )
            for (station in listOf(a, b)) {
                val vehicles = station.vehicles.first { it.keys == setOf(1, 2) }
                vehicles.getValue(2).params.read("DISARM_DELAY").value shouldBe 10.0
            }
        }
    }

    "listening outputs move by the vehicle's index, so each vehicle listens on ports of its own" {
        runTest(timeout = 1.minutes) {
            val timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
            val network = MemoryNetwork(backgroundScope, timebase)
            val outputs = listOf(LinkAddress.parse("udpin:127.0.0.1:14570"), LinkAddress.parse("udpin:127.0.0.1:14580"))
            val fleet = SimFleet.start(
                2, backgroundScope, SimVehicleConfig(systemId = 1, gcs = outputs.first().toString()),
                timebase = timebase, openLink = FanOutOpener(outputs, LinkOpener.memory(network)),
            )
            val station = GroundStation.open(network.open("udpout://127.0.0.1:14581"), backgroundScope, GroundStationConfig(timebase = timebase))
            station.vehicles.first { 2 in it }.keys shouldBe setOf(2)
            fleet.stop()
        }
    }
})
