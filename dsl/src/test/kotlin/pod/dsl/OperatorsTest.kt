package pod.dsl

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.matchers.types.shouldBeSameInstanceAs
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.test.currentTime
import kotlinx.coroutines.test.runTest
import pod.core.engine.Condition
import pod.core.engine.ConditionScope
import pod.core.engine.EngineConfig
import pod.core.engine.ErrorHandler
import pod.core.engine.Task
import pod.core.vehicle.Battery
import pod.dsl.TinyFleet.Companion.mission
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/** Reads flows as they are now, to evaluate a built condition. */
private object Now : ConditionScope {
    override fun <T> read(flow: StateFlow<T>): T = flow.value
}

private fun Condition.holdsNow(): Boolean = with(this) { Now.holds() }

class OperatorsTest : FunSpec({
    val fleet = TinyFleet(2)
    val (v1, v2) = fleet.tiny
    val a = mission("a") on v1
    val b = mission("b") on v2
    val c = mission("c") on v1

    test("a then b then c flattens to one Sequence of the three tasks in order") {
        val seq = (a then b then c).shouldBeInstanceOf<Task.Sequence>()
        seq.tasks shouldContainExactly listOf(a, b, c)
    }

    test("a and b is a Concurrent of both; a and b and c flattens") {
        (a and b).shouldBeInstanceOf<Task.Concurrent>().tasks shouldContainExactly listOf(a, b)
        (a and b and c).shouldBeInstanceOf<Task.Concurrent>().tasks shouldContainExactly listOf(a, b, c)
    }

    test("mixing then and and nests instead of flattening: (a then b) and c") {
        val both = ((a then b) and c).shouldBeInstanceOf<Task.Concurrent>()
        both.tasks[0].shouldBeInstanceOf<Task.Sequence>().tasks shouldContainExactly listOf(a, b)
        both.tasks[1] shouldBeSameInstanceAs c
    }

    test("mission on v binds a Fly of that mission to exactly v") {
        val bound = (mission("survey") on v1).shouldBeInstanceOf<Task.Bound>()
        bound.task.shouldBeInstanceOf<Task.Fly>().mission.name shouldBe "survey"
        bound.vehicles.ids shouldBe setOf(1)
        (mission("pair") on listOf(v1, v2)).shouldBeInstanceOf<Task.Bound>().vehicles.ids shouldBe setOf(1, 2)
    }

    test("t until { … } wraps t with a condition over live state") {
        val until = (a until { battery(v1) < 0.3 }).shouldBeInstanceOf<Task.Until>()
        until.task shouldBeSameInstanceAs a
        until.condition.holdsNow() shouldBe false
        v1.battery.value = Battery(0.2, 16.8)
        until.condition.holdsNow() shouldBe true
        v1.battery.value = Battery(1.0, 16.8)
    }

    test("waitFor { } then t waits for the condition, then runs t") {
        val wait = (waitFor { battery(v2) > 0.5 } then b).shouldBeInstanceOf<Task.WaitFor>()
        wait.task shouldBeSameInstanceAs b
        wait.condition.holdsNow() shouldBe true
    }

    test("allOf { whenever { … } then t } collects one branch per whenever; oneOf likewise, with otherwise") {
        val all = allOf {
            whenever { battery(v1) < 0.5 } then a
            whenever { true } then b
        }.shouldBeInstanceOf<Task.AllOf>()
        all.branches.map { it.task } shouldContainExactly listOf(a, b)
        all.branches.map { it.condition.holdsNow() } shouldContainExactly listOf(false, true)
        val one = oneOf {
            whenever { false } then a
            otherwise(c)
        }.shouldBeInstanceOf<Task.OneOf>()
        one.branches.map { it.task } shouldContainExactly listOf(a, c)
    }

    test("watch(t) onError ignore, propagate, or a recovery task") {
        (watch(a) onError ignore).shouldBeInstanceOf<Task.Watch>().onError shouldBe ErrorHandler.Ignore
        (watch(a) onError propagate).shouldBeInstanceOf<Task.Watch>().onError shouldBe ErrorHandler.Propagate
        val recover = (watch(a) onError { _: Throwable -> c }).shouldBeInstanceOf<Task.Watch>().onError
        recover.shouldBeInstanceOf<ErrorHandler.Recover>().recover(IllegalStateException()) shouldBeSameInstanceAs c
    }

    test("t during 5.minutes limits t; idle waits") {
        val during = (a during 5.minutes).shouldBeInstanceOf<Task.During>()
        during.limit shouldBe 5.minutes
        during.task shouldBeSameInstanceAs a
        idle(30.seconds).shouldBeInstanceOf<Task.Idle>().time shouldBe 30.seconds
    }

    test("a program written with the DSL runs end to end on a fleet in virtual time") {
        runTest {
            val tiny = TinyFleet(2)
            val said = tiny.program(EngineConfig(timebase = virtualTimebase())) {
                val v = pick { count(2); payload("camera") }
                val (first, second) = v.members
                execute(
                    ((mission("survey", steps = 100) on first) until { battery(first) < 0.75 }) and
                        (waitFor { battery(first) < 0.9 } then (mission("relay", steps = 2) on second)),
                )
                execute(watch(mission("long", steps = 100) on first during 1.minutes) onError ignore)
                execute(action("report") { message("done") } then idle(10.seconds))
                release(v)
                picked.value
            }
            said shouldBe emptySet()
            // survey: 3 steps (battery 1.0 → 0.7), relay starts after 2 steps and flies 2; during stops long after 6 steps.
            tiny.completed shouldContainExactly listOf(2 to "relay")
            tiny.madeSafe shouldContainExactly listOf(1, 1)
            currentTime shouldBe (40 + 60 + 10) * 1000L
        }
    }
})
