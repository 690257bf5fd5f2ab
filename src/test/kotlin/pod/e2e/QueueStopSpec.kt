package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.queue.WhenEmpty
import pod.core.queue.at
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.dsl.queue.goto
import pod.mavlink.queue.QueueFlight
import pod.sim.SimVehicleConfig
import kotlin.math.hypot
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * `next` on a fast copter: the queue runs empty while the copter flies at 10 m/s, and it stops
 * where its braking takes it (its autopilot's hold) instead of turning back to where `next` found it.
 */
class QueueStopSpec : StringSpec({
    for ((label, config) in listOf(
        "ArduCopter" to SimVehicleConfig(systemId = 71, parameters = mapOf("WPNAV_SPEED" to 1000.0)),
        "PX4 copter" to SimVehicleConfig(systemId = 72, autopilot = Autopilot.PX4, parameters = mapOf("MPC_XY_CRUISE" to 10.0, "MPC_XY_VEL_MAX" to 12.0)),
    )) {
        "$label: next at 10 m/s stops the copter within its braking distance, and it does not fly back" {
            virtualRun(seed = 21, timeout = 3.minutes) {
                flying(config) { v, sim ->
                    Flights.keepArmedOnGround(v)
                    v.action.arm()
                    v.action.takeoff(30.m)
                    val queue = v.queue
                    val flight = async { QueueFlight(v, queue).fly(WhenEmpty.WAIT) }
                    queue.append(goto(at(400.m, 0.m), altitude = 30.m))
                    val home = v.telemetry.home.value!!
                    fun north() = home.northEastTo(sim.state.value.location).first.meters
                    withTimeout(2.minutes) { sim.state.first { home.northEastTo(it.location).first.meters > 150 && it.groundSpeed.metersPerSecond > 9.0 } }
                    val skippedAt = north()
                    queue.next()
                    var farthest = skippedAt
                    var back = 0.0
                    val until = sim.clock + 40.seconds
                    sim.state.first { s ->
                        val n = home.northEastTo(s.location).first.meters
                        farthest = maxOf(farthest, n)
                        back = maxOf(back, farthest - n)
                        s.time >= until
                    }
                    withClue("metres past the point where next was called") { (farthest - skippedAt) shouldBeLessThan 30.0 }
                    withClue("metres flown back after stopping") { back shouldBeLessThan 1.0 }
                    hypot(sim.state.value.velocityNed.first.metersPerSecond, sim.state.value.velocityNed.second.metersPerSecond) shouldBeLessThan 0.3
                    flight.cancel()
                }
            }
        }
    }
})
