package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.comparables.shouldBeGreaterThanOrEqualTo
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.Autopilot
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.VehicleType
import pod.mavlink.FleetEvent
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

class StreamRateSpec : StringSpec({

    "the ground station asks each vehicle it finds for its configured stream rates" {
        coroutineScope {
            val wanted = mapOf(33 to 10.0, 1 to 0.5)
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(streamRates = wanted))
            val sim = SimVehicle(SimVehicleConfig(systemId = 9, gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
            try {
                sim.streamRates.value[33] shouldBe 2.0
                sim.start(this)
                val rates = withTimeout(10.seconds) { sim.streamRates.first { it[33] == 10.0 && it[1] == 0.5 } }
                rates[30] shouldBe SimVehicleConfig.DEFAULT_STREAM_RATES[30] // not asked, unchanged
            } finally {
                sim.stop()
                gcs.close()
            }
        }
    }
})
