package pod.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.survey.SurveySpacing
import pod.core.units.m
import pod.core.vehicle.LandedState
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.dsl.survey.on
import pod.dsl.survey.pass
import pod.dsl.survey.surveyWorkflow
import pod.mavlink.MessageIds
import pod.sim.SimFlavor
import java.util.Collections
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * One way into the air from whatever state a vehicle is found in: freshly booted (its landed state
 * not heard yet, GUIDED refused until its estimator has a position while it would already arm in
 * STABILIZE), or left in RTL, BRAKE, AUTO or PX4's Land by an earlier flight.
 */
class AirborneSpec : StringSpec({
    "a survey task on a freshly booted ArduCopter, landed state unknown and GUIDED refused for want of a position, switches mode first, waits, arms, takes off and surveys" {
        // Home (and so `pick`) at 5 s, arming at 5 s, GUIDED only at 25 s: real SITL shows such a window.
        val booting = { c: pod.sim.SimVehicleConfig -> c.copy(positionReadyAfter = 5.seconds, sensorsReadyAfter = 5.seconds, navigationReadyAfter = 25.seconds) }
        virtualRun(seed = 31, timeout = 4.minutes, withheld = setOf(MessageIds.EXTENDED_SYS_STATE)) {
            val (said, record) = simulate(listOf(SimFlavor.ARDUCOPTER), configure = booting) { sim ->
                val texts = Collections.synchronizedList(ArrayList<String>())
                val listening = launch { sim.simulated.single().statusTexts.collect { texts += it } }
                val v = pick { count(1) }[0]
                val home = v.home.value!!
                val field = listOf(0 to 0, 0 to 40, 40 to 40, 40 to 0).map { (n, e) -> home.offset((n + 20).m, e.m) }
                val survey = surveyWorkflow(field, 20.m, SurveySpacing.Direct(20.m), forward = { pass(Unit) }, backward = { })
                execute(survey on v)
                listening.cancel()
                texts.toList()
            }
            said shouldContain "Mode change to GUIDED failed: requires position"
            withClue("it armed only once in GUIDED: never armed in STABILIZE") { said.none { it.startsWith("Arm") } shouldBe true }
            val track = record.tracks.values.single().second
            val home = track.first()
            track.maxOf { it.altitude.meters - home.altitude.meters } shouldBeGreaterThan 18.0
        }
    }

    for ((flavor, leftIn) in listOf(SimFlavor.ARDUCOPTER to "RTL", SimFlavor.ARDUCOPTER to "BRAKE", SimFlavor.PX4 to "AUTO.LAND")) {
        "${flavor.name} left disarmed on the ground in $leftIn takes off again, saying what it changed" {
            virtualRun(seed = 32, timeout = 3.minutes) {
                withVehicle(flavor) { _, _, vehicle, _ ->
                    Flights.keepArmedOnGround(vehicle)
                    vehicle.action.getAirborne(10.m)
                    if (leftIn == "RTL") vehicle.action.returnToLaunch() else vehicle.action.land()
                    vehicle.action.awaitLanded(3.minutes)
                    if (leftIn == "BRAKE") vehicle.action.setMode("BRAKE")
                    vehicle.telemetry.mode.value!!.name shouldBe leftIn
                    val changed = vehicle.action.getAirborne(15.m)
                    changed.first() shouldBe "mode $leftIn → ${if (flavor == SimFlavor.PX4) "AUTO.LOITER" else "GUIDED"}"
                    changed.drop(1) shouldBe listOf("armed", "took off to 15.0 m")
                    vehicle.telemetry.position.value!!.relativeAltitude.meters shouldBeGreaterThan 14.0
                    vehicle.action.getAirborne(15.m) shouldBe emptyList()
                }
            }
        }
    }

    // PX4 SITL: `pod takeoff 10` right after connecting failed 19 times in 20 ("home altitude unknown").
    "PX4: a takeoff asked before the vehicle's home altitude is heard waits for it instead of failing" {
        virtualRun(seed = 34, timeout = 3.minutes) {
            withheld += setOf(MessageIds.HOME_POSITION, MessageIds.GLOBAL_POSITION_INT)
            heard(pod.sim.SimVehicleConfig(systemId = 81, autopilot = pod.core.vehicle.Autopilot.PX4)) { vehicle, _ ->
                Flights.keepArmedOnGround(vehicle)
                vehicle.action.arm()
                vehicle.telemetry.position.value shouldBe null
                val heardLater = launch {
                    kotlinx.coroutines.delay(2.seconds)
                    withheld.clear()
                }
                vehicle.action.takeoff(10.m)
                heardLater.join()
                vehicle.telemetry.position.value!!.relativeAltitude.meters shouldBeGreaterThan 9.0
            }
        }
    }

    "an ArduCopter left disarmed in AUTO by a mission that landed arms for the next start from an armable mode (pod start --arm)" {
        virtualRun(seed = 33, timeout = 3.minutes) {
            val (landedIn, _) = simulate(listOf(SimFlavor.ARDUCOPTER)) { sim ->
                val v = pick { count(1) }[0]
                val home = v.home.value!!
                execute(mission("hop") { home(home); takeOff(10.m); move(north = 20.m); returnHomeAndLand() } on v)
                val vehicle = sim.platform.mavlink(v)
                withTimeout(2.minutes) { vehicle.telemetry.landedState.first { it == LandedState.ON_GROUND } }
                val landedIn = vehicle.telemetry.mode.value!!.name
                vehicle.action.armForFlight() shouldBe listOf("mode AUTO → GUIDED", "armed")
                vehicle.action.startMission()
                withTimeout(1.minutes) { vehicle.telemetry.position.first { it != null && it.relativeAltitude.meters > 5.0 } }
                landedIn
            }
            landedIn shouldBe "AUTO"
        }
    }
})
