package pod.e2e

import kotlinx.coroutines.flow.collect
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlin.math.abs
import kotlin.math.hypot
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.mission.LoiterDuration
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.platform.MissionEvent
import pod.core.units.deg
import pod.core.units.m
import pod.core.vehicle.LandedState
import pod.mavlink.plan.MissionFlavor
import pod.mavlink.plan.MissionPlanner
import pod.sim.SimFlavor

/** ArduPlane behaviour that only shows when Pod's missions meet the real firmware's rules (issue 11). */
class PlaneMissionSpec : StringSpec({

    "a plane mission ending in an unlimited loiter reports loitering once the plane circles the loiter point, not on its way there" {
        // 10×: position reports close enough together to see where the plane was when the run completed.
        virtualRun { withVehicle(SimFlavor.ARDUPLANE) { fleet, v, vehicle, sim ->
            val home = sim.config.home
            val center = home.at(800, 0, 50.0)
            // returnHomeAndLoiter's radius: the plane flies the tightest circle it can (~29 m in the simulator).
            val mission = Mission("loiter", null, listOf(MissionStep.TakeOff(home.at(0, 0, 40.0), 15.deg), MissionStep.Loiter(center, 15.m, LoiterDuration.Unlimited)))
            // Where the plane is when the run reports completion (at 30× it flies on 450 m a second).
            var atCompletion: pod.core.vehicle.Position? = null
            withTimeout(30.minutes) { fleet.flyUntilLoitering(v, mission) { if (it is MissionEvent.Loitering) atCompletion = vehicle.telemetry.position.value } }
            val p = atCompletion!!
            val d = p.location.distanceTo(center.copy(altitude = p.location.altitude)).meters
            d shouldBeLessThan 50.0
            // Moving along the circle, not towards its centre.
            val n = (p.location.latitude - center.latitude) * 111_320.0
            val e = (p.location.longitude - center.longitude) * 111_320.0 * kotlin.math.cos(Math.toRadians(center.latitude))
            val radial = abs(p.velocityNorth.metersPerSecond * n + p.velocityEast.metersPerSecond * e) / hypot(n, e)
            radial shouldBeLessThan 0.4 * hypot(p.velocityNorth.metersPerSecond, p.velocityEast.metersPerSecond)
            vehicle.telemetry.mode.value!!.name shouldBe "AUTO"
        } }
    }

    "a plane left disarmed in AUTO by an earlier program arms and flies the next mission (clearing sends it to RTL, where it cannot arm)" {
        virtualRun { withVehicle(SimFlavor.ARDUPLANE) { fleet, v, vehicle, sim ->
            val home = sim.config.home
            val earlier = Mission("earlier", null, listOf(MissionStep.TakeOff(home.at(0, 0, 40.0), 15.deg), MissionStep.Waypoint(home.at(0, 600, 40.0))))
            vehicle.mission.upload(MissionPlanner.plan(earlier, MissionFlavor.ARDUPLANE, home).items)
            vehicle.action.setMode("AUTO")
            val texts = ArrayList<String>()
            val collecting = launch { sim.statusTexts.collect { texts += it } }
            // Far enough that the flight outlasts a few heartbeats at 30×: a mission flown between two
            // heartbeats would never show AUTO to the start's confirmation.
            val next = Mission("next", null, listOf(MissionStep.TakeOff(home.at(0, 0, 40.0), 15.deg), MissionStep.Waypoint(home.at(3000, 0, 50.0))))
            withTimeout(30.minutes) { fleet.fly(v, next).collect() }
            collecting.cancel()
            texts shouldContain "Aircraft in auto without a running mission"
            vehicle.telemetry.armed.value shouldBe true
            vehicle.telemetry.position.value!!.relativeAltitude.meters shouldBeGreaterThan 30.0
        } }
    }

    "replacing the mission of a plane flying its mission in AUTO holds it at height, replaces the mission and flies the new one" {
        virtualRun { withVehicle(SimFlavor.ARDUPLANE) { fleet, v, vehicle, sim ->
            val home = sim.config.home
            val first = Mission("first", null, listOf(MissionStep.TakeOff(home.at(0, 0, 40.0), 15.deg), MissionStep.Loiter(home.at(400, 0, 50.0), 80.m, LoiterDuration.Unlimited)))
            withTimeout(30.minutes) { fleet.flyUntilLoitering(v, first) }
            vehicle.telemetry.mode.value!!.name shouldBe "AUTO"
            var lowest = Double.MAX_VALUE
            val watching = launch { vehicle.telemetry.position.collect { p -> if (p != null) lowest = minOf(lowest, p.relativeAltitude.meters) } }
            val end = home.at(0, 600, 60.0)
            val second = Mission("second", null, listOf(MissionStep.Waypoint(home.at(300, 300, 60.0)), MissionStep.Loiter(end, 80.m, LoiterDuration.Unlimited)))
            withTimeout(30.minutes) { fleet.flyUntilLoitering(v, second) }
            watching.cancel()
            lowest shouldBeGreaterThan 40.0
            vehicle.telemetry.position.value!!.location.distanceTo(end.copy(altitude = vehicle.telemetry.position.value!!.location.altitude)).meters shouldBeLessThan 100.0
        } }
    }

    "returnHomeAndLand on a plane (a waypoint over home, then land there) touches down near home, after a glide of a few degrees" {
        virtualRun { withVehicle(SimFlavor.ARDUPLANE) { fleet, v, vehicle, sim ->
            val home = sim.config.home
            val mission = Mission(
                "home", null,
                listOf(
                    MissionStep.TakeOff(home.at(0, 0, 40.0), 15.deg),
                    MissionStep.Waypoint(home.at(600, 0, 60.0)),
                    MissionStep.Waypoint(home.at(0, 0, 60.0)),
                    MissionStep.Land(home.at(0, 0, 0.0)),
                ),
            )
            val texts = ArrayList<String>()
            val collecting = launch { sim.statusTexts.collect { texts += it } }
            withTimeout(45.minutes) { fleet.fly(v, mission).collect() }
            collecting.cancel()
            val slope = texts.first { it.startsWith("Landing glide slope") }.removePrefix("Landing glide slope ").removeSuffix(" degrees").toDouble()
            slope shouldBeLessThan 8.0
            vehicle.telemetry.landedState.value shouldBe LandedState.ON_GROUND
            vehicle.telemetry.position.value!!.location.distanceTo(home.copy(altitude = vehicle.telemetry.position.value!!.location.altitude)).meters shouldBeLessThan 60.0
        } }
    }
})
