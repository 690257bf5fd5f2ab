package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.engine.EngineEvent
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.LandedState
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.mavlink.executor.MissionInterrupted
import pod.mavlink.mission.MissionType
import pod.mavlink.plan.FencePolygon
import pod.mavlink.plan.PlanGeoFence
import pod.mavlink.plan.PlanLists
import pod.mavlink.plan.PlanPoint
import pod.sim.SimFlavor
import java.util.Collections
import kotlin.time.Duration.Companion.minutes

/** A square inclusion fence reaching [half] metres north, south, east and west of [home]. */
private fun squareAround(home: Location, half: Double) = PlanGeoFence(
    polygons = listOf(
        FencePolygon(
            inclusion = true,
            listOf(-half to -half, -half to half, half to half, half to -half).map { (n, e) -> home.offset(n.m, e.m).let { PlanPoint(it.latitude, it.longitude) } },
        ),
    ),
)

/**
 * Fences mean something in a simulated flight: a Pod mission that leaves the fence is ended by the
 * autopilot's fence action, Pod's task fails with the autopilot's own reason, and Pod does not
 * override the autopilot by making the vehicle "safe" its own way.
 */
class FenceFlightSpec : StringSpec({
    // ArduCopter: FENCE_ENABLE 1 (off by default), FENCE_ACTION 1 at its default: RTL, "Polygon fence breached".
    // PX4: the uploaded geofence is live at once, GF_ACTION 2 at its default: Hold (AUTO.LOITER), "Failsafe activated".
    for ((flavor, expected) in listOf(SimFlavor.ARDUCOPTER to ("RTL" to "Polygon fence breached"), SimFlavor.PX4 to ("AUTO.LOITER" to "Failsafe activated"))) {
        "a ${flavor.name} mission flying out of its uploaded fence fails with the fence action's mode and the autopilot's words, and the vehicle is left to that action" {
            virtualRun(timeout = 4.minutes) {
                val events = Collections.synchronizedList(ArrayList<EngineEvent>())
                val enableFence = { c: pod.sim.SimVehicleConfig -> if (flavor == SimFlavor.ARDUCOPTER) c.copy(parameters = c.parameters + ("FENCE_ENABLE" to 1.0)) else c }
                val (outcome, record) = simulate(listOf(flavor), onEvent = { events += it }, configure = enableFence) { sim ->
                    val v = pick { count(1) }[0]
                    val home = v.home.value!!
                    val vehicle = sim.platform.mavlink(v)
                    vehicle.mission.upload(PlanLists.fenceItems(squareAround(home, 60.0)), MissionType.FENCE)
                    val failure = shouldThrow<MissionInterrupted> {
                        execute(mission("out of the fence") { home(home); takeOff(15.m); move(north = 150.m); returnHomeAndLand() } on v)
                    }
                    val modeAfter = vehicle.telemetry.mode.value?.name
                    // What the fence action does next, unhindered: ArduCopter flies home and lands.
                    if (flavor == SimFlavor.ARDUCOPTER) withTimeout(10.minutes) { vehicle.telemetry.landedState.first { it == LandedState.ON_GROUND } }
                    Triple(failure, modeAfter, vehicle.telemetry.position.value!!.location to home)
                }
                val (failure, modeAfter, ended) = outcome
                val (at, home) = ended
                failure.mode shouldBe expected.first
                failure.said shouldContain expected.second
                failure.message!! shouldContain "\"${expected.second}\""
                modeAfter shouldBe expected.first
                withClue("Pod made no safe state of its own over the autopilot's fence action") {
                    events.filterIsInstance<EngineEvent.MadeSafe>() shouldBe emptyList()
                }
                val track = record.tracks.values.single().second
                val farthestNorth = track.maxOf { (it.latitude - home.latitude) * 111_132.0 }
                // Breached at the 60 m edge: stopped within a braking distance of it, never near the 150 m waypoint.
                farthestNorth shouldBeGreaterThan 60.0
                farthestNorth shouldBeLessThan 75.0
                when (flavor) {
                    SimFlavor.ARDUCOPTER -> at.copy(altitude = home.altitude).distanceTo(home).meters shouldBeLessThan 3.0
                    else -> at.copy(altitude = home.altitude).distanceTo(home).meters shouldBeGreaterThan 55.0
                }
            }
        }
    }
})
