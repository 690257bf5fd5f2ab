package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import pod.core.engine.EngineEvent
import pod.core.platform.MissionEvent
import pod.core.platform.PlatformVehicle
import pod.core.units.m
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleLost
import pod.core.vehicle.VehicleType
import pod.dsl.concurrently
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.mavlink.GroundStationConfig
import pod.sim.SimFlavor
import pod.sim.fault.LinkFaults
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** A hop for a copter: up, out and back down home. */
private fun hop(v: PlatformVehicle) = mission("hop ${v.name}") {
    home(v.home.value!!)
    takeOff(15.m)
    move(north = 40.m)
    returnHomeAndLand()
}


/**
 * Programs on fleets of mixed autopilots and airframes, through the engine, in virtual time on a
 * memory network: what a behaviour test can afford now that vehicle minutes cost no wall time.
 */
class MixedFleetSpec : StringSpec({

    "an ArduPlane, a PX4 copter and an ArduCopter fly one program together and all land" {
        virtualRun { mixedProgram() }
    }

    "the mixed program over a lossy link (20 % lost each way, some reordered) run twice with one seed gives the same events" {
        val faults = LinkFaults(drop = 0.2, reorder = 0.02, delay = 3.milliseconds, jitter = 2.milliseconds)
        val traces = List(2) {
            var trace: List<String> = emptyList()
            // Heartbeats cross the same lossy link: allow more silence before calling a vehicle lost.
            virtualRun(seed = 21, up = faults, down = faults) { trace = mixedProgram(GroundStationConfig(lostAfter = 10.seconds)).trace() }
            trace
        }
        traces[1] shouldBe traces[0]
    }

    "of two copters, the one whose simulator stops mid-mission fails the program with VehicleLost; the other was flying" {
        virtualRun {
            val lost = shouldThrow<VehicleLost> {
                simulate(listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4)) { sim ->
                    val (a, b) = pick { count(2) }.toList()
                    coroutineScope {
                        launch {
                            sim.platform.mavlink(b).telemetry.position.first { (it?.relativeAltitude?.meters ?: 0.0) > 10.0 }
                            sim[b.id].stop()
                        }
                        execute(concurrently(hop(a) on a, hop(b) on b))
                    }
                }
            }
            lost.systemId shouldBe 2
        }
    }
})

/** Plane, PX4 copter and ArduCopter fly their missions at once; checked; the events. */
private suspend fun VirtualFleet.mixedProgram(station: GroundStationConfig = GroundStationConfig()): List<EngineEvent> {
    val (vehicles, record) = simulate(listOf(SimFlavor.ARDUPLANE, SimFlavor.PX4, SimFlavor.ARDUCOPTER), station = station) {
        val plane = pick { count(1); type(VehicleType.FIXED_WING) }[0]
        val copters = pick { count(2); type(VehicleType.QUADROTOR) }.toList()
        execute(concurrently(listOf(circuit(plane) on plane) + copters.map { hop(it) on it }))
        listOf(plane) + copters
    }
    record.events.filterIsInstance<EngineEvent.Mission>().count { it.event == MissionEvent.Completed } shouldBe 3
    for (v in vehicles) {
        v.landedState.value shouldBe LandedState.ON_GROUND
        val limit = if (v.type == VehicleType.FIXED_WING) 80.0 else 3.0
        v.home.value!!.distanceTo(v.position.value!!.location.copy(altitude = v.home.value!!.altitude)).meters shouldBeLessThan limit
    }
    record.events.size shouldBeGreaterThan 20
    return record.events
}
