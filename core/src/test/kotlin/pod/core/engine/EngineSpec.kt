package pod.core.engine

import pod.core.time.virtualTimebase
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.currentTime
import kotlinx.coroutines.test.runTest
import pod.core.engine.FakeFleet.Companion.mission
import pod.core.platform.MissionEvent
import pod.core.platform.PlatformVehicle
import pod.core.platform.SafeState
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.VehicleLost
import pod.core.vehicle.VehicleType
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

private fun fly(name: String, vararg on: PlatformVehicle, steps: Int = 3) = Task.Bound(Task.Fly(mission(name, steps)), VehicleSet(on.toList()))

private fun TestScope.engine(fleet: FakeFleet) = Engine(fleet, EngineConfig(timebase = virtualTimebase()))

class EngineSpec : FunSpec({
    test("a sequence flies its missions one after the other, a concurrency all at once") {
        runTest {
            val fleet = FakeFleet(2)
            engine(fleet).run {
                execute(Task.Sequence(listOf(fly("a", fleet[1]), fly("b", fleet[1]))))
                currentTime shouldBe 60_000
                execute(Task.Concurrent(listOf(fly("c", fleet[1]), fly("d", fleet[2]))))
                currentTime shouldBe 90_000
            }
            fleet.completed.value shouldContainExactly listOf(1 to "a", 1 to "b", 1 to "c", 2 to "d")
        }
    }

    test("until cancels the task when the condition fires and the vehicle holds before until returns") {
        runTest {
            val fleet = FakeFleet(1, drainPerStep = 0.1)
            val v = fleet[1]
            engine(fleet).run {
                execute(Task.Until(fly("survey", v, steps = 100), Condition { battery(v) < 0.75 }))
                fleet.madeSafe.value shouldContainExactly listOf(1 to SafeState.HOLD)
                fleet.airborne.shouldBeEmpty()
            }
            currentTime shouldBe 30_000 + 1_000
            fleet.completed.value.shouldBeEmpty()
        }
    }

    test("waitFor runs its task only once the condition holds") {
        runTest {
            val fleet = FakeFleet(1)
            val v = fleet[1]
            v.setBattery(0.5)
            val job = launch { engine(fleet).run { execute(Task.WaitFor(Condition { battery(v) > 0.9 }, fly("go", v))) } }
            testScheduler.advanceTimeBy(5.minutes)
            fleet.flights.value.shouldBeEmpty()
            v.setBattery(1.0)
            job.join()
            fleet.completed.value shouldContainExactly listOf(1 to "go")
        }
    }

    test("allOf runs every branch when its own condition holds; oneOf runs only the first that holds") {
        runTest {
            val fleet = FakeFleet(3)
            val (a, b, c) = fleet.fakes
            a.setBattery(0.2)
            engine(fleet).run {
                execute(
                    Task.AllOf(
                        listOf(
                            Branch(Condition { battery(a) < 0.5 }, fly("low", a)),
                            Branch(Condition { true }, fly("any", b)),
                        ),
                    ),
                )
                execute(
                    Task.OneOf(
                        listOf(
                            Branch(Condition { battery(b) < 0.1 }, fly("never", b)),
                            Branch(Condition { battery(c) > 0.9 }, fly("first", c)),
                            Branch(Condition { true }, fly("second", a)),
                        ),
                    ),
                )
            }
            fleet.completed.value.map { it.second }.sorted() shouldContainExactly listOf("any", "first", "low")
        }
    }

    test("during cancels its task when the limit passes, in vehicle time, and completes normally") {
        runTest {
            val fleet = FakeFleet(1, timeScale = 10.0)
            engine(fleet).run { execute(Task.During(2.minutes, fly("long", fleet[1], steps = 100))) }
            currentTime shouldBe 12_000 + 1_000
            fleet.madeSafe.value shouldContainExactly listOf(1 to SafeState.HOLD)
        }
    }

    test("a failure in one concurrent branch cancels its sibling, which is made safe, and propagates") {
        runTest {
            val fleet = FakeFleet(2)
            val error = shouldThrow<IllegalStateException> {
                engine(fleet).run { execute(Task.Concurrent(listOf(fly("fail-1", fleet[1]), fly("ok", fleet[2], steps = 50)))) }
            }
            error.message shouldContain "fail-1"
            fleet.madeSafe.value.toSet() shouldBe setOf(1 to SafeState.HOLD, 2 to SafeState.HOLD)
            fleet.airborne.shouldBeEmpty()
        }
    }

    test("a flight whose autopilot took control fails without Pod making its vehicle safe over the autopilot; its cancelled sibling is made safe") {
        runTest {
            val fleet = FakeFleet(2)
            val error = shouldThrow<TookControl> {
                engine(fleet).run { execute(Task.Concurrent(listOf(fly("failsafe-1", fleet[1]), fly("ok", fleet[2], steps = 50)))) }
            }
            error.message shouldContain "took control"
            fleet.madeSafe.value shouldContainExactly listOf(2 to SafeState.HOLD)
        }
    }

    test("watch with ignore swallows a failure, propagate passes it on, recover runs another task") {
        runTest {
            val fleet = FakeFleet(1)
            val v = fleet[1]
            engine(fleet).run {
                execute(Task.Sequence(listOf(Task.Watch(fly("fail-a", v), ErrorHandler.Ignore), fly("after", v))))
                shouldThrow<IllegalStateException> { execute(Task.Watch(fly("fail-b", v), ErrorHandler.Propagate)) }
                execute(Task.Watch(fly("fail-c", v), ErrorHandler.Recover { fly("rescue", v) }))
            }
            fleet.completed.value shouldContainExactly listOf(1 to "after", 1 to "rescue")
        }
    }

    test("a vehicle is never in two running tasks: the second gets VehicleBusy") {
        runTest {
            val fleet = FakeFleet(1)
            val busy = shouldThrow<VehicleBusy> {
                engine(fleet).run { execute(Task.Concurrent(listOf(fly("one", fleet[1]), fly("two", fleet[1])))) }
            }
            busy.vehicleId shouldBe 1
            fleet.overlaps.value shouldBe 0
        }
    }

    test("a mission with no vehicles fails at once with UnboundTask") {
        runTest {
            val fleet = FakeFleet(1)
            shouldThrow<UnboundTask> { engine(fleet).run { execute(Task.Fly(mission("loose"))) } }.message shouldContain "loose"
        }
    }

    test("pick waits for matching vehicles, never hands out a picked one, and the program's end releases them") {
        runTest {
            val fleet = FakeFleet(3)
            fleet[2].setBattery(0.4)
            val engine = engine(fleet)
            engine.run {
                val two = pick(PickRequest(count = 2, minBattery = 0.5))
                two.ids shouldBe setOf(1, 3)
                val waiting = launch { pick(PickRequest(count = 1, minBattery = 0.5)).ids shouldBe setOf(3) }
                testScheduler.advanceTimeBy(10.seconds)
                waiting.isActive shouldBe true
                release(fleet[3])
                waiting.join()
                picked.value shouldBe setOf(1, 3)
            }
            engine.run { pick(PickRequest(count = 3, minBattery = 0.0)).size shouldBe 3 }
        }
    }

    test("a pick for a payload waits until a vehicle reports carrying it") {
        runTest {
            val fleet = FakeFleet(1)
            val v = fleet[1]
            v.payloads.value = emptySet()
            engine(fleet).run {
                val picking = launch { pick(PickRequest(count = 1, payloads = setOf("camera"))).ids shouldBe setOf(1) }
                testScheduler.advanceTimeBy(10.seconds)
                picking.isActive shouldBe true
                v.payloads.value = setOf("camera")
                picking.join()
            }
        }
    }

    test("an unknown battery is neither full nor empty: no low-battery condition fires and a battery pick waits until it is reported") {
        runTest {
            val fleet = FakeFleet(1)
            val v = fleet[1]
            v.battery.value = null
            engine(fleet).run {
                battery(v).isNaN() shouldBe true
                batteryKnown(v) shouldBe false
                await(Condition { !batteryKnown(v) && !(battery(v) < 0.3) && !(battery(v) > 0.5) })
                val low = launch { await(Condition { battery(v) < 0.3 }) }
                val picking = launch { pick(PickRequest(count = 1, minBattery = 0.5)).ids shouldBe setOf(1) }
                testScheduler.advanceTimeBy(10.seconds)
                low.isActive shouldBe true
                picking.isActive shouldBe true
                v.setBattery(0.9) // now known and full enough: the pick goes through, the low condition still does not fire
                picking.join()
                low.isActive shouldBe true
                v.setBattery(0.2)
                low.join()
            }
        }
    }

    test("a pick that cannot be met times out naming what it asked for") {
        runTest {
            val fleet = FakeFleet(2)
            val error = shouldThrow<PickTimeout> {
                engine(fleet).run { pick(PickRequest(count = 3, types = setOf(VehicleType.FIXED_WING), timeout = 30.seconds)) }
            }
            error.message shouldContain "3 vehicles of type FIXED_WING"
            error.matching shouldBe 0
            currentTime shouldBe 30_000
        }
    }

    test("a vehicle that goes silent fails its task with VehicleLost after the connection timeout") {
        runTest {
            val fleet = FakeFleet(1)
            val v = fleet[1]
            val failure = launch(start = CoroutineStart.UNDISPATCHED) {
                shouldThrow<VehicleLost> {
                    engine(fleet).run {
                        connectionTimeout = 20.seconds
                        execute(fly("far", v, steps = 100))
                    }
                }.systemId shouldBe 1
            }
            testScheduler.advanceTimeBy(30.seconds)
            v.connection.value = ConnectionState.LOST
            testScheduler.advanceTimeBy(10.seconds)
            v.connection.value = ConnectionState.CONNECTED
            testScheduler.advanceTimeBy(30.seconds)
            failure.isActive shouldBe true
            v.connection.value = ConnectionState.LOST
            failure.join()
            currentTime shouldBe 70_000 + 20_000
            fleet.madeSafe.value.shouldBeEmpty()
        }
    }

    test("cancelling the program makes every flying vehicle safe before it returns, returning home when asked") {
        runTest {
            val fleet = FakeFleet(3)
            val engine = engine(fleet)
            val program = launch {
                engine.run {
                    val all = pick(PickRequest(count = 3))
                    execute(
                        Task.Concurrent(
                            listOf(
                                fly("a", all[0], steps = 100),
                                Task.Bound(Task.Fly(mission("b", 100), SafeState.RETURN_HOME), all[1].asSet()),
                                fly("c", all[2], steps = 100),
                            ),
                        ),
                    )
                }
            }
            engine.busy.first { it.size == 3 }
            testScheduler.advanceTimeBy(25.seconds)
            program.cancelAndJoin()
            fleet.madeSafe.value.toMap() shouldBe mapOf(1 to SafeState.HOLD, 2 to SafeState.RETURN_HOME, 3 to SafeState.HOLD)
            engine.busy.value shouldBe emptyMap()
            fleet.airborne.shouldBeEmpty()
        }
    }

    test("conditions are evaluated again only when what they read changes") {
        runTest {
            val fleet = FakeFleet(1)
            val v = fleet[1]
            var evaluations = 0
            val job = launch { engine(fleet).run { await(Condition { evaluations++; battery(v) < 0.2 }) } }
            testScheduler.advanceTimeBy(10.minutes)
            evaluations shouldBe 1
            v.setBattery(0.5)
            testScheduler.advanceTimeBy(1.milliseconds)
            evaluations shouldBe 2
            v.setBattery(0.1)
            job.join()
            evaluations shouldBe 3
        }
    }

    test("events tell each task's start and end and what its vehicles reported") {
        runTest {
            val fleet = FakeFleet(1)
            val engine = engine(fleet)
            val events = mutableListOf<EngineEvent>()
            val collector = launch(start = CoroutineStart.UNDISPATCHED) { engine.events.collect { events += it } }
            engine.run { execute(Task.Sequence(listOf(fly("a", fleet[1], steps = 1)))) }
            testScheduler.advanceUntilIdle()
            collector.cancel()
            val shape = events.map {
                when (it) {
                    is EngineEvent.TaskStarted -> "start ${it.label}"
                    is EngineEvent.TaskCompleted -> "done ${it.label}"
                    is EngineEvent.Mission -> it.event::class.simpleName
                    else -> it::class.simpleName
                }
            }
            shape shouldContainExactly listOf(
                "start sequence", "start a on [fake-1]", "start a",
                "Flying", "Uploaded", "Started", "StepStarted", "StepDone", "Completed",
                "done a", "done a on [fake-1]", "done sequence", "ProgramEnded",
            )
            (events.last().at) shouldBe 10.seconds
            events.filterIsInstance<EngineEvent.Mission>().map { it.event }.last() shouldBe MissionEvent.Completed
        }
    }
})
