package pod.core.engine

import pod.core.time.virtualTimebase
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.test.runTest
import pod.core.queue.QueueNeedsOneVehicle
import pod.core.queue.QueueUnsupported

/** The engine's side of queue tasks; flying them is the MAVLink platform's (e2e QueueFlightSpec, QueueProgramSpec). */
class QueueTaskSpec : FunSpec({
    test("a queue task bound to two vehicles fails at once: a queue steers one vehicle") {
        runTest {
            val fleet = FakeFleet(2)
            val engine = Engine(fleet, EngineConfig(timebase = virtualTimebase()))
            val failure = shouldThrow<QueueNeedsOneVehicle> {
                engine.run { execute(Task.Bound(Task.FlyQueue(missionQueue()), VehicleSet(listOf(fleet[1], fleet[2])))) }
            }
            failure.vehicles shouldBe 2
        }
    }

    test("a queue task without vehicles is unbound, and a platform that cannot fly queues says so") {
        runTest {
            val fleet = FakeFleet(1)
            val engine = Engine(fleet, EngineConfig(timebase = virtualTimebase()))
            shouldThrow<UnboundTask> { engine.run { execute(Task.FlyQueue(missionQueue())) } }.message shouldContain "queue"
            shouldThrow<QueueUnsupported> { engine.run { execute(Task.Bound(Task.FlyQueue(missionQueue()), VehicleSet(listOf(fleet[1])))) } }
                .message shouldContain "cannot fly a mission queue"
            fleet.madeSafe.value shouldBe listOf(1 to pod.core.platform.SafeState.HOLD)
        }
    }
})
