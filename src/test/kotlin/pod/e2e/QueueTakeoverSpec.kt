package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.engine.EngineEvent
import pod.core.queue.at
import pod.core.units.m
import pod.core.vehicle.LandedState
import pod.dsl.action
import pod.dsl.concurrently
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.dsl.queue.goto
import pod.dsl.queue.on
import pod.mavlink.queue.QueueInterrupted
import pod.sim.SimFlavor
import java.util.Collections
import kotlin.time.Duration.Companion.minutes

/**
 * A queue flight (and so waypoint actions and surveys, which fly one) that the vehicle's autopilot
 * or another ground station takes over ends at once, typed, and is left to them: Pod neither steers
 * on (its next goto would switch the mode back) nor makes the vehicle "safe" its own way.
 */
class QueueTakeoverSpec : StringSpec({
    for (flavor in listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4)) {
        "${flavor.name}: a queue flight switched to RTL from elsewhere fails with QueueInterrupted and the vehicle flies its RTL home" {
            virtualRun(seed = 41, timeout = 4.minutes) {
                val events = Collections.synchronizedList(ArrayList<EngineEvent>())
                val (failure, record) = simulate(listOf(flavor), onEvent = { events += it }) { sim ->
                    val v = pick { count(1) }[0]
                    val home = v.home.value!!
                    execute(mission("up") { home(home); takeOff(25.m) } on v)
                    val queue = missionQueue()
                    queue.append(goto(at(300.m, 0.m)))
                    val vehicle = sim.platform.mavlink(v)
                    val failure = shouldThrow<QueueInterrupted> {
                        execute(
                            concurrently(
                                queue on v,
                                action("another station") {
                                    vehicle.telemetry.position.first { it != null && home.northEastTo(it.location).first.meters > 60 }
                                    vehicle.action.returnToLaunch()
                                },
                            ),
                        )
                    }
                    withTimeout(5.minutes) { vehicle.telemetry.landedState.first { it == LandedState.ON_GROUND } }
                    failure
                }
                failure.mode shouldBe if (flavor == SimFlavor.PX4) "AUTO.RTL" else "RTL"
                withClue("no safe state of Pod's own over the autopilot's") { events.filterIsInstance<EngineEvent.MadeSafe>().shouldBeEmpty() }
                val track = record.tracks.values.single().second
                val home = track.first()
                track.maxOf { home.northEastTo(it).first.meters } shouldBeLessThan 120.0
                track.last().copy(altitude = home.altitude).distanceTo(home).meters shouldBeLessThan 3.0
            }
        }
    }
})
