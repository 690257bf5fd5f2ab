package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.comparables.shouldBeLessThan
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.delay
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.mavlink.MavlinkVehicle
import pod.core.workflow.OnFailure
import pod.mavlink.workflow.Stop
import pod.core.workflow.WaypointActionFailed
import pod.mavlink.workflow.NothingReported
import pod.mavlink.workflow.WaypointFlight
import pod.mavlink.workflow.measureRange
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** Waypoint actions (I-Seed's action_job): stop, hold, run code, go on; failures by policy. */
class WaypointFlightSpec : StringSpec({

    for (autopilot in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
        "$autopilot copter: the action runs once at each chosen waypoint while the vehicle holds on it, in order" {
            virtualRun(seed = 17) { flying(SimVehicleConfig(systemId = 81, autopilot = autopilot)) { v, sim ->
                val home = up(v)
                val points = square(home)
                val seen = mutableListOf<Triple<Int, Double, Double>>() // index, metres off the point, ground speed
                val records = WaypointFlight(v).fly(points, Stop(at = { it != 2 }) { visit ->
                    val s = sim.state.value
                    seen += Triple(visit.index, s.location.copy(altitude = visit.point.altitude).distanceTo(absolute(visit.point, home)).meters, s.groundSpeed.metersPerSecond)
                    delay(2.seconds)
                    visit.index * 10
                })
                seen.map { it.first } shouldBe listOf(0, 1, 3, 4)
                seen.forEach { (_, off, speed) ->
                    off shouldBeLessThan 2.5
                    speed shouldBeLessThan 0.5
                }
                records.map { it.result } shouldBe listOf(0, 10, null, 30, 40)
                // Stopped within seconds of arriving, held for the action, and left within a fraction
                // of a second of its end (vehicle time): the stop's cost is the braking, not the link.
                records.filter { it.index != 2 }.forEach { r ->
                    (r.began!! - r.reached) shouldBeLessThan 5.seconds
                    (r.left - r.began!! - 2.seconds) shouldBeLessThan 200.milliseconds
                }
                records[2].began shouldBe null
                records.zipWithNext().forEach { (a, b) -> (b.reached > a.left) shouldBe true }
            } }
        }
    }

    "over a 100 ms round trip the vehicle holds on the waypoint itself while the action runs, not where a round-trip-old position put it" {
        val slow = LinkFaults(delay = 50.milliseconds)
        virtualRun(seed = 19, up = slow, down = slow) { flying(SimVehicleConfig(systemId = 83)) { v, sim ->
            val home = up(v)
            val points = square(home)
            val off = mutableListOf<Double>() // metres off the point as each action ends
            WaypointFlight(v).fly(points, Stop { visit ->
                delay(4.seconds)
                off += sim.state.value.location.copy(altitude = visit.point.altitude).distanceTo(absolute(visit.point, home)).meters
            })
            off.size shouldBe points.size
            off.forEach { it shouldBeLessThan 0.5 }
        } }
    }

    "a failing action is skipped, retried or ends the flight, as its policy says; a slow one times out" {
        virtualRun(seed = 18) { flying(SimVehicleConfig(systemId = 82)) { v, _ ->
            val home = up(v)
            val points = square(home).take(3)
            val skipped = WaypointFlight(v).fly(points, Stop(timeout = 3.seconds) { visit ->
                when (visit.index) {
                    0 -> error("camera busy")
                    1 -> { delay(10.seconds); "late" }
                    else -> "ok"
                }
            })
            skipped.map { it.result } shouldBe listOf(null, null, "ok")
            skipped[1].let { (it.left - it.began!!) shouldBeLessThan 3.5.seconds } // the 3 s timeout, not the 10 s action

            var calls = 0
            val retried = WaypointFlight(v).fly(points.take(1), Stop(onFailure = OnFailure.Retry(2)) { if (++calls < 3) error("no fix") else "fix" })
            retried.single().result shouldBe "fix"
            retried.single().tries shouldBe 3

            val height = v.telemetry.position.value!!.relativeAltitude.meters
            val failure = shouldThrow<WaypointActionFailed> { WaypointFlight(v).fly(points, Stop(onFailure = OnFailure.Abort) { error("rangefinder dead") }) }
            failure.index shouldBe 0
            failure.message!!.contains("rangefinder dead") shouldBe true
            v.telemetry.position.value!!.relativeAltitude.meters shouldBeGreaterThan height - 2.0 // still up: nothing descended
        } }
    }

    "a photo on simulated ArduCopter is confirmed by its CAMERA_FEEDBACK (ArduPilot 4.7 sends no CAMERA_IMAGE_CAPTURED); every wait that runs out says what it waited for" {
        virtualRun(seed = 21) { flying(SimVehicleConfig(systemId = 84)) { v, sim ->
            val home = up(v)
            val records = WaypointFlight(v).fly(square(home).take(2), Stop(onFailure = OnFailure.Abort) { visit -> visit.takePhoto() })
            records.map { it.result!!.index } shouldBe listOf(1, 2) // ArduPilot numbers its images from 1
            sim.photos.value.size shouldBe 2
            records.forEach { r -> r.result!!.location.distanceTo(absolute(r.point, home)).meters shouldBeLessThan 2.5 }

            // No rangefinder: the wait names the message it waited for.
            shouldThrow<NothingReported> { v.measureRange(3.seconds) }.message shouldBe
                "vehicle 84 reported no downward rangefinder reading (DISTANCE_SENSOR) within 3.0 s"
            val late = shouldThrow<WaypointActionFailed> {
                WaypointFlight(v).fly(square(home).take(1), Stop(timeout = 2.seconds, onFailure = OnFailure.Abort) { delay(5.seconds) })
            }
            late.message shouldBe "the action at waypoint 0 failed after 1 try: the action at waypoint 0 did not finish within its time limit of 2.0 s"
        } }
    }
}) {
    private companion object {
        suspend fun up(v: MavlinkVehicle): Location {
            Flights.keepArmedOnGround(v)
            v.action.arm()
            v.action.takeoff(25.m)
            return v.telemetry.home.value!!
        }

        /** Five waypoints 40 m apart at 25 m above home (altitudes above home). */
        fun square(home: Location): List<Location> =
            listOf(40 to 0, 40 to 40, 0 to 40, -40 to 40, -40 to 0).map { (n, e) -> home.offset(n.m, e.m).copy(altitude = 25.m) }

        fun absolute(point: Location, home: Location): Location = point.copy(altitude = (home.altitude.meters + point.altitude.meters).m)
    }
}
