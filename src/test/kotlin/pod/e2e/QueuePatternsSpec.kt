package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.mission.SurveyDirection
import pod.core.mission.SurveyPlanner
import pod.core.queue.EndReason
import pod.core.queue.QueueEvent
import pod.core.queue.at
import pod.core.units.m
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType
import pod.dsl.queue.hold
import pod.dsl.queue.land
import pod.dsl.queue.returnHome
import pod.dsl.queue.survey
import pod.mavlink.queue.QueueFlight
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/** The patterns QueueFlightSpec's scenario does not fly: survey, hold, land and return home, on each autopilot. */
class QueuePatternsSpec : StringSpec({

    for (flavour in Flavour.entries) {
        val plane = flavour.config.type == VehicleType.FIXED_WING
        val ending = if (plane) "returns home and circles there" else "lands where it is"
        "${flavour.label}: a queued survey visits its waypoints in order, a 20 s hold keeps the vehicle where it was, and it $ending" {
            virtualRun(seed = 16) { flying(flavour.config) { v, sim ->
                val k = flavour.scale
                Flights.keepArmedOnGround(v)
                v.action.arm()
                v.action.takeoff((if (plane) 60 else 25).m)
                val home = v.telemetry.home.value!!
                val queue = v.queue
                val ended = mutableListOf<EndReason>()
                val recording = launch { queue.events.filterIsInstance<QueueEvent.Ended>().collect { ended += it.reason } }
                val track = FlownTrack(queue, sim, home)
                val sampling = track.start(this)
                val flight = async { QueueFlight(v, queue).fly() }
                queue.append(survey(at((20 * k).m, (20 * k).m), length = (60 * k).m, width = (40 * k).m, spacing = (20 * k).m, altitude = 30.m))
                queue.append(hold(20.seconds))
                val holdStarted = queue.events.filterIsInstance<QueueEvent.Started>().let { starts ->
                    withTimeout(30.minutes) { starts.first { it.entry.element.pattern == pod.core.queue.QueuePattern.Hold } }
                }
                queue.append(if (plane) returnHome() else land())
                withTimeout(30.minutes) { flight.await() }
                sampling.cancel()
                recording.cancel()

                ended shouldBe listOf(EndReason.ARRIVED, EndReason.ELAPSED, EndReason.ARRIVED)
                // The survey's waypoints, in order.
                val waypoints = SurveyPlanner.lawnMower(home.offset((20 * k).m, (20 * k).m), (60 * k).m, (40 * k).m, (20 * k).m, SurveyDirection.NORTH_EAST, 30.m)
                    .map { home.northEastTo(it).let { (n, e) -> n.meters to e.meters } }
                val near = if (plane) 110.0 else 3.5
                val visits = waypoints.map { p -> track.samples.indexOfFirst { it.distanceTo(p.first, p.second) < near } }
                visits.none { it < 0 } shouldBe true
                visits shouldBe visits.sorted()
                // The hold: a copter stays put, a plane circles the spot, both at their height.
                val held = track.between(holdStarted.at + 5.seconds, holdStarted.at + 19.seconds)
                val spot = held.first()
                held.forEach { it.distanceTo(spot.north, spot.east) shouldBeLessThan (if (plane) 200.0 else 3.0) }
                held.forEach { kotlin.math.abs(it.height - 30.0) shouldBeLessThan 3.0 }
                if (plane) {
                    track.last().distanceTo(0.0, 0.0) shouldBeLessThan 110.0
                } else {
                    v.telemetry.landedState.value shouldBe LandedState.ON_GROUND
                    val end = track.last()
                    end.distanceTo(held.last().north, held.last().east) shouldBeLessThan 3.0
                }
            } }
        }
    }
})
