package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeLessThanOrEqualTo
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

class FleetDiscoverySpec : StringSpec({

    "three simulated vehicles on one ground-station port are found with their type, autopilot and position" {
        coroutineScope {
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this)
            val configs = listOf(
                SimVehicleConfig(systemId = 1, type = VehicleType.QUADROTOR, autopilot = Autopilot.ARDUPILOT),
                SimVehicleConfig(systemId = 2, type = VehicleType.FIXED_WING, autopilot = Autopilot.ARDUPILOT),
                SimVehicleConfig(systemId = 3, type = VehicleType.QUADROTOR, autopilot = Autopilot.PX4),
            ).mapIndexed { i, c ->
                c.copy(gcs = "udpout://127.0.0.1:${gcs.link.localPort}", home = c.home.offset(pod.core.units.Distance(20.0 * i), pod.core.units.Distance(0.0)))
            }
            val sims = configs.map { SimVehicle(it) }
            try {
                sims.forEach { it.start(this) }
                val fleet = withTimeout(10.seconds) {
                    gcs.awaitFleetWithPositions(3)
                }
                fleet.keys shouldContainExactlyInAnyOrder listOf(1, 2, 3)
                for (config in configs) {
                    val v = fleet.getValue(config.systemId)
                    v.identity.value.type shouldBe config.type
                    v.identity.value.autopilot shouldBe config.autopilot
                    val at = v.telemetry.position.value!!.location
                    at.latitude shouldBe (config.home.latitude plusOrMinus 1e-6)
                    at.longitude shouldBe (config.home.longitude plusOrMinus 1e-6)
                    at.altitude.meters shouldBe (config.home.altitude.meters plusOrMinus 0.01)
                    v.connection.value shouldBe ConnectionState.CONNECTED
                }
                fleet.getValue(1).telemetry.mode.first { it != null }!!.name shouldBe "STABILIZE"
                fleet.getValue(2).telemetry.mode.first { it != null }!!.name shouldBe "MANUAL"
                fleet.getValue(3).telemetry.mode.first { it != null }!!.name shouldBe "AUTO.LOITER"
            } finally {
                sims.forEach { it.stop() }
                gcs.close()
            }
        }
    }

    "a stopped vehicle is marked lost after the configured silence and found again when it restarts (virtual time)" {
        virtualRun {
            coroutineScope {
                val lostAfter = 1500.milliseconds
                val gcs = station(this, GroundStationConfig(lostAfter = lostAfter))
                val sims = (1..3).map { vehicle(SimVehicleConfig(systemId = it), gcs) }
                try {
                    sims.forEach { it.start(this) }
                    withTimeout(10.seconds) { gcs.vehicles.first { it.size == 3 } }

                    val lost = async(start = CoroutineStart.UNDISPATCHED) { gcs.events.filterIsInstance<FleetEvent.Lost>().first() }
                    sims[1].stop()
                    val stoppedAt = timebase.clock.markNow()
                    val event = withTimeout(lostAfter + 5.seconds) { lost.await() }
                    event.vehicle.systemId shouldBe 2
                    event.silence shouldBeGreaterThanOrEqualTo lostAfter
                    // Found lost within one silence check of lostAfter, in virtual time.
                    stoppedAt.elapsedNow() shouldBeLessThanOrEqualTo lostAfter + 1.seconds
                    event.vehicle.connection.value shouldBe ConnectionState.LOST
                    gcs.vehicles.value.getValue(1).connection.value shouldBe ConnectionState.CONNECTED
                    gcs.vehicles.value.getValue(3).connection.value shouldBe ConnectionState.CONNECTED

                    val regained = async(start = CoroutineStart.UNDISPATCHED) { gcs.events.filterIsInstance<FleetEvent.Regained>().first() }
                    sims[1].start(this)
                    withTimeout(5.seconds) { regained.await() }.vehicle.systemId shouldBe 2
                    gcs.vehicles.value.getValue(2).connection.value shouldBe ConnectionState.CONNECTED
                    gcs.vehicles.value.size shouldBe 3
                } finally {
                    sims.forEach { it.stop() }
                    gcs.close()
                }
            }
        }
    }
})
