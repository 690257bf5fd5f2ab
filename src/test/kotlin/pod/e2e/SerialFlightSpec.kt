package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeGreaterThanOrEqualTo
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.LandedState
import pod.mavlink.FleetEvent
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.link.ByteStreamLink
import pod.mavlink.link.LinkState
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * Pod's station on one end of a socat pty pair at 57600 baud, a simulated vehicle on the other:
 * what a telemetry radio link does, unplugging included.
 */
class SerialFlightSpec : StringSpec({

    "over a 57600-baud serial pair the station finds a copter, its telemetry flows without a gap, and a parameter write and an arm are acknowledged" {
        Socat.pair().use { pair ->
            serialFlight(pair, SimVehicleConfig(systemId = 41)) { gcs, vehicle, _ ->
                withTimeout(15.seconds) { vehicle.telemetry.linkQuality.first { it.received >= 200 } }.lost shouldBe 0
                gcs.stats.value.badCrc shouldBe 0
                vehicle.params.write("DISARM_DELAY", 0.0)
                vehicle.params.read("DISARM_DELAY").value shouldBe 0.0
                vehicle.action.arm()
                withTimeout(10.seconds) { vehicle.telemetry.armed.first { it } }
                (gcs.link as ByteStreamLink).counters.droppedSends shouldBe 0
            }
        }
    }

    "a radio unplugged mid-flight: the vehicle is lost, regained when the device is back, and its mission completes" {
        Socat.pair().use { pair ->
            val config = SimVehicleConfig(systemId = 42, timeScale = 5.0)
            serialFlight(pair, config, GroundStationConfig(lostAfter = 1.seconds)) { gcs, vehicle, _ ->
                val home = config.home
                vehicle.mission.upload(Flights.copterLeg(home, side = 200.0))
                Flights.keepArmedOnGround(vehicle)
                vehicle.action.arm()
                vehicle.action.startMission()
                withTimeout(1.minutes) { vehicle.telemetry.landedState.first { it == LandedState.IN_AIR } }

                val lost = eventAsync<FleetEvent.Lost>(gcs)
                val regained = eventAsync<FleetEvent.Regained>(gcs)
                runInterruptible(Dispatchers.IO) { pair.unplug() }
                withTimeout(10.seconds) { lost.await() }.vehicle.systemId shouldBe 42
                vehicle.connection.value shouldBe ConnectionState.LOST
                (gcs.link as ByteStreamLink).state.value::class shouldBe LinkState.Down::class

                runInterruptible(Dispatchers.IO) { pair.plugIn() }
                withTimeout(15.seconds) { regained.await() }.vehicle.systemId shouldBe 42
                // Still flying the mission the autopilot kept while nobody heard it.
                vehicle.telemetry.landedState.value shouldBe LandedState.IN_AIR

                vehicle.action.awaitLanded(timeout = 3.minutes)
                vehicle.telemetry.armed.value shouldBe false
                vehicle.telemetry.position.value!!.location.distanceTo(home).meters shouldBeLessThan 3.0
                val link = gcs.link as ByteStreamLink
                link.counters.outages shouldBe 1
                link.counters.reopens shouldBeGreaterThanOrEqualTo 1
            }
        }
    }
})

/**
 * A station on [pair]'s end a and a simulated vehicle ([config]) on end b, both at 57600 baud;
 * runs [block] once the station has the vehicle ready, then stops both.
 */
private suspend fun serialFlight(
    pair: Socat,
    config: SimVehicleConfig,
    station: GroundStationConfig = GroundStationConfig(),
    block: suspend CoroutineScope.(GroundStation, MavlinkVehicle, SimVehicle) -> Unit,
) = coroutineScope {
    val gcs = GroundStation.open("serial://${pair.a}:57600", this, station)
    val sim = SimVehicle(config.copy(gcs = "${pair.b},57600"))
    try {
        sim.start(this)
        block(gcs, Flights.vehicle(gcs, config.systemId), sim)
    } finally {
        sim.stop()
        gcs.close()
    }
}

private inline fun <reified E : FleetEvent> CoroutineScope.eventAsync(gcs: GroundStation) =
    async(start = CoroutineStart.UNDISPATCHED) { gcs.events.filterIsInstance<E>().first() }
