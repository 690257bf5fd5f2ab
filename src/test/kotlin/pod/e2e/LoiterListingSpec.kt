package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.engine.EngineEvent
import pod.core.platform.MissionEvent
import pod.core.units.m
import pod.core.vehicle.LandedState
import pod.samples.loiterUntilLowBattery
import pod.sim.SimFlavor
import kotlin.time.Duration.Companion.minutes

/**
 * Dolphin's Listing 2 as written (move, loiter indefinitely, `until` the battery is low, then home)
 * on each simulated autopilot: the loiter lasts until the battery condition, never less, and the
 * way home keeps the cruise height until the landing.
 */
class LoiterListingSpec : StringSpec({
    for (flavor in listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4, SimFlavor.ARDUPLANE)) {
        "${flavor.name}: Listing 2 loiters until the battery is low, then lands at home, never below its cruise height away from home" {
            virtualRun(timeout = 6.minutes) {
                val plane = flavor == SimFlavor.ARDUPLANE
                val (v, record) = simulate(listOf(flavor)) { sim ->
                    val v = loiterUntilLowBattery(lowBattery = 0.85, out = if (plane) 800.m else 150.m, radius = if (plane) 80.m else 15.m)
                    withTimeout(20.minutes) { sim.platform.mavlink(v).telemetry.armed.first { !it } }
                    v
                }
                val loiter = record.events.filterIsInstance<EngineEvent.Flying>().single { it.mission.name.startsWith("loiter") }
                val reports = record.events.filterIsInstance<EngineEvent.Mission>().filter { it.task == loiter.task }.map { it.event }
                reports.filterIsInstance<MissionEvent.Loitering>().size shouldBe 1
                reports.contains(MissionEvent.Completed) shouldBe false
                // Cancelled by the battery condition: the message after it names the battery then.
                val said = record.events.filterIsInstance<EngineEvent.Message>().single { "returning home" in it.text }.text
                val battery = Regex("battery at (\\d+) %").find(said)!!.groupValues[1].toInt()
                withClue(said) { battery shouldBe 84 }
                v.landedState.value shouldBe LandedState.ON_GROUND
                val home = v.home.value!!
                v.position.value!!.location.copy(altitude = home.altitude).distanceTo(home).meters shouldBeLessThan if (plane) 150.0 else 3.0
                val track = record.tracks.values.single().second
                val awayFromHome = if (plane) 500.0 else 20.0
                val far = track.filter { it.copy(altitude = home.altitude).distanceTo(home).meters > awayFromHome }
                withClue("lowest height more than $awayFromHome m from home") { far.minOf { it.altitude.meters - home.altitude.meters } shouldBeGreaterThan 27.0 }
            }
        }
    }
})
