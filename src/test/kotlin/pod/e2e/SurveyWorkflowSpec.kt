package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldNotBeEmpty
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.survey.CameraTrigger
import pod.core.survey.PolygonSurvey
import pod.core.survey.SurveySpacing
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.core.workflow.AltitudeCorrection
import pod.core.workflow.Forward
import pod.mavlink.workflow.SurveyWorkflow
import pod.sim.SimDetections
import pod.sim.SimVehicleConfig
import pod.sim.world.Hill
import pod.sim.world.Rangefinder
import pod.sim.world.SimObject
import pod.sim.world.Terrain

/**
 * The I-Seed workflow on simulated drones with seeded objects: a forward pass photographs every
 * waypoint of a polygon survey, its detections are the seeded objects in each photo's footprint,
 * the backward pass revisits exactly the waypoints that saw something, and the vehicle ends landed
 * at home.
 */
class SurveyWorkflowSpec : StringSpec({

    for (autopilot in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
        "$autopilot copter: forward photos detect the seeded objects, the backward pass revisits exactly the flagged waypoints, and it lands at home" {
            val home = SimVehicleConfig.DEFAULT_HOME
            val objects = SimObject.scatter(seed = 5, count = 6, center = home.offset(70.m, 60.m), radius = 60.m)
            val config = SimVehicleConfig(systemId = 91, autopilot = autopilot, objects = objects)
            virtualRun(seed = 19) { flying(config) { v, sim ->
                val plan = upAndPlanned(v, home)
                val revisited = mutableListOf<Int>()
                val run = SurveyWorkflow(v).run(
                    plan,
                    forward = { visit ->
                        val image = visit.takePhoto()
                        val seen = SimDetections.parse(image.fileUrl)!!.ids
                        Forward(flagged = seen.isNotEmpty(), value = seen)
                    },
                    backward = { visit -> revisited += visit.index; "measured" },
                )

                val photoWaypoints = plan.waypoints.indices.filter { plan.waypoints[it].photo }
                run.forward.map { it.index } shouldBe photoWaypoints
                // What the ground learnt is what the simulated camera saw, photo by photo.
                val truth = sim.photos.value.map { photo -> photo.detected.map { it.id }.sorted() }
                run.forward.map { it.result!!.value.sorted() } shouldBe truth
                val flagged = run.forward.filter { it.result!!.flagged }.map { it.index }
                flagged.shouldNotBeEmpty()
                run.backward.map { it.first }.sorted() shouldBe flagged.sorted()
                run.backward.forEach { it.second.result shouldBe "measured" }
                revisited.size shouldBe flagged.size
                (flagged.size < photoWaypoints.size) shouldBe true // some photos saw nothing: the backward pass is a real subset
                v.telemetry.landedState.value shouldBe LandedState.ON_GROUND
                v.telemetry.position.value!!.location.copy(altitude = home.altitude).distanceTo(home.copy(altitude = home.altitude)).meters shouldBeLessThan 3.0
            } }
        }
    }

    for (autopilot in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
        "$autopilot copter: over a hill the rangefinder's readings raise the remaining waypoints, so every photo is taken at the survey's height above the ground" {
            val home = SimVehicleConfig.DEFAULT_HOME
            val hill = Hill(north = 70.m, east = 60.m, height = 14.m, radius = 35.m)
            val terrain = Terrain(origin = home, hills = listOf(hill))
            val config = SimVehicleConfig(systemId = 92, autopilot = autopilot, terrain = terrain, rangefinder = Rangefinder())
            virtualRun(seed = 20) { flying(config) { v, sim ->
                val plan = upAndPlanned(v, home)
                val correction = AltitudeCorrection(target = 30.m, tolerance = 2.m, minimum = 10.m, maximum = 80.m)
                val run = SurveyWorkflow(v, altitudeCorrection = correction).run(
                    plan,
                    forward = { _ -> Forward(flagged = false, value = sim.state.value.heightAboveGround.meters) },
                    backward = { _ -> Unit },
                )
                run.backward shouldBe emptyList()
                val rise = run.forward.map { r -> terrain.elevationAt(r.point).meters - home.altitude.meters }
                rise.max() shouldBeGreaterThan 8.0 // some photos are over the hill
                run.forward.forEach { r -> kotlin.math.abs(r.result!!.value - 30.0) shouldBeLessThan 4.0 }
                run.forward.maxOf { it.altitudeOffset.meters } shouldBeGreaterThan 5.0
                v.telemetry.landedState.value shouldBe LandedState.ON_GROUND
            } }
        }
    }
}) {
    private companion object {
        /** Takes [v] up to 30 m and plans a photo survey of a 140 × 120 m area north-east of [home], entered nearest the vehicle. */
        suspend fun upAndPlanned(v: pod.mavlink.MavlinkVehicle, home: pod.core.units.Location): pod.core.survey.SurveyPlan {
            Flights.keepArmedOnGround(v)
            v.action.arm()
            v.action.takeoff(30.m)
            val corners = listOf(0 to 0, 0 to 120, 140 to 120, 140 to 0).map { (n, e) -> home.offset(n.m, e.m) }
            return PolygonSurvey.plan(corners, 30.m, SurveySpacing.Direct(40.m, 30.m), trigger = CameraTrigger.PER_WAYPOINT, start = v.telemetry.position.value!!.location)
        }
    }
}
