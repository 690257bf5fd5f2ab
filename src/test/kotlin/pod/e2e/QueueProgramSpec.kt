package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.launch
import pod.core.engine.EngineEvent
import pod.core.platform.SafeState
import pod.core.queue.EndReason
import pod.core.queue.QueueEvent
import pod.core.queue.at
import pod.core.units.m
import pod.dsl.action
import pod.dsl.concurrently
import pod.dsl.during
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.dsl.queue.circle
import pod.dsl.queue.goto
import pod.dsl.queue.on
import pod.sim.SimFlavor
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/** A queue as a task in programs: fed while it flies, composed with the engine's operators. */
class QueueProgramSpec : StringSpec({

    "a program flies a queue that another task feeds; the queue task completes when the queue runs empty, the vehicle holding in the air" {
        virtualRun {
            val (result, record) = simulate(listOf(SimFlavor.ARDUCOPTER)) {
                val v = pick { count(1) }[0]
                execute(mission("up") { home(v.home.value!!); takeOff(25.m) } on v)
                val queue = missionQueue()
                val ended = mutableListOf<EndReason>()
                coroutineScope {
                    val recording = launch { queue.events.filterIsInstance<QueueEvent.Ended>().collect { ended += it.reason } }
                    queue.append(goto(at(40.m, 0.m)))
                    execute(
                        concurrently(
                            queue on v,
                            action("feed") {
                                queue.append(goto(at(40.m, 40.m)))
                                queue.append(circle(at(10.m, 40.m), (-12).m, duration = 40.seconds))
                            },
                        ),
                    )
                    recording.cancel()
                }
                Triple(ended.toList(), v.position.value!!.relativeAltitude.meters, queue.state.value.isEmpty)
            }
            val (ended, height, empty) = result
            ended shouldBe listOf(EndReason.ARRIVED, EndReason.ARRIVED, EndReason.ELAPSED)
            empty shouldBe true
            height shouldBeGreaterThan 22.0
            record.events.filterIsInstance<EngineEvent.TaskCompleted>().map { it.label } shouldContain "queue"
        }
    }

    "a queue task cut short by `during` makes its vehicle safe, and the program goes on" {
        virtualRun {
            val (_, record) = simulate(listOf(SimFlavor.ARDUCOPTER)) {
                val v = pick { count(1) }[0]
                execute(mission("up") { home(v.home.value!!); takeOff(20.m) } on v)
                val queue = missionQueue()
                queue.append(circle(at(0.m, 30.m), 15.m)) // never ends by itself
                execute((queue on v) during 2.minutes)
                message("after the queue")
            }
            val made = record.events.filterIsInstance<EngineEvent.MadeSafe>().single()
            made.state shouldBe SafeState.HOLD
            made.confirmed shouldBe true
            record.events.filterIsInstance<EngineEvent.Message>().map { it.text } shouldContain "after the queue"
        }
    }
})
