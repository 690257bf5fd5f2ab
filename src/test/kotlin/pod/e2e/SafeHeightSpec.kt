package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThanOrEqual
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import pod.core.engine.EngineEvent
import pod.core.units.m
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.mavlink.MessageIds
import pod.mavlink.command.CommandRejected
import pod.sim.SimFlavor
import java.util.Collections
import kotlin.time.Duration.Companion.minutes

/**
 * Pod never sends a vehicle along the ground: the README's "home" mission (`home(h);
 * returnHomeAndLand()`, flown by a vehicle already in the air) keeps the height it flies at until
 * it is over home, on every autopilot; and a flight that fails on the ground leaves the vehicle's
 * mode alone.
 */
class SafeHeightSpec : StringSpec({
    for (flavor in listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4)) {
        "${flavor.name}: the home mission flown from 30 m stays at 30 m until it is over home, then lands there" {
            virtualRun(timeout = 4.minutes) {
                val (_, record) = simulate(listOf(flavor)) { sim ->
                    val v = pick { count(1) }[0]
                    val home = v.home.value!!
                    execute(mission("out") { home(home); takeOff(30.m); move(north = 55.m) } on v)
                    execute(mission("home") { home(home); returnHomeAndLand() } on v)
                    sim.simulated.single().state.value.crashed.shouldBeNull()
                }
                val home = record.flights.first().second.home!!
                val track = record.tracks.values.single().second
                val away = track.filter { it.copy(altitude = home.altitude).distanceTo(home).meters > 3.0 && it.latitude > home.latitude }
                val lowestAway = away.filter { (it.latitude - home.latitude) * 111_132.0 > 5.0 }.minOf { it.altitude.meters - home.altitude.meters }
                withClue("lowest height more than 5 m from home on the way back") { lowestAway shouldBeGreaterThan 28.0 }
                track.last().copy(altitude = home.altitude).distanceTo(home).meters shouldBeLessThanOrEqual 2.0
            }
        }
    }

    "a mission at the current height planned for a vehicle on the ground is refused before anything is sent" {
        virtualRun {
            simulate(listOf(SimFlavor.PX4)) {
                val v = pick { count(1) }[0]
                val failure = shouldThrow<pod.mavlink.executor.MissionNotFlyable> {
                    execute(mission("home") { home(v.home.value!!); returnHomeAndLand() } on v)
                }
                failure.message!! shouldContain "step 1 (a waypoint) is 0.0 m above home"
            }
        }
    }

    // The vehicle's landed state is unknown (no EXTENDED_SYS_STATE heard), as on a freshly connected
    // ArduCopter before its streams are asked for.
    "a flight that fails on the ground leaves a disarmed vehicle's mode alone, even with its landed state unknown" {
        virtualRun(withheld = setOf(MessageIds.EXTENDED_SYS_STATE)) {
            val events = Collections.synchronizedList(ArrayList<EngineEvent>())
            val low = { c: pod.sim.SimVehicleConfig -> c.copy(initialCharge = 0.1) }
            val (mode, _) = simulate(listOf(SimFlavor.ARDUCOPTER), onEvent = { events += it }, configure = low) { sim ->
                val v = pick { count(1) }[0]
                val failure = shouldThrow<CommandRejected> { execute(mission("up") { home(v.home.value!!); takeOff(20.m) } on v) }
                failure.message!! shouldContain "Battery 1 below minimum arming voltage"
                sim.platform.mavlink(v).telemetry.mode.value?.name
            }
            mode shouldBe "GUIDED"
            events.filterIsInstance<EngineEvent.MadeSafe>().map { it.state.name } shouldBe listOf("HOLD")
            events.filterIsInstance<EngineEvent.MadeSafe>().filter { !it.confirmed }.shouldBeEmpty()
        }
    }
})
