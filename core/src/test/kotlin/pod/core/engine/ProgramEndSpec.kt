package pod.core.engine

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import pod.core.time.virtualTimebase

/** The engine says when a program's code is done, so a consumer of its events knows where one run ends. */
class ProgramEndSpec : FunSpec({
    test("each program's end is an event naming it, after its code's last event and before the release of what it still held") {
        runTest {
            val fleet = FakeFleet(1)
            val engine = Engine(fleet, EngineConfig(timebase = virtualTimebase()))
            val events = mutableListOf<EngineEvent>()
            val collector = launch(start = CoroutineStart.UNDISPATCHED) { engine.events.collect { events += it } }
            val first = engine.run {
                pick(PickRequest(count = 1))
                message("picked")
                id
            }
            val failed = runCatching { engine.run<Unit> { error("the program's own failure") } }
            testScheduler.advanceUntilIdle()
            collector.cancel()
            first shouldBe 1
            failed.exceptionOrNull()?.message shouldBe "the program's own failure"
            events.map { it::class.simpleName } shouldContainExactly listOf("Picked", "Message", "ProgramEnded", "Released", "ProgramEnded")
            events.filterIsInstance<EngineEvent.ProgramEnded>().map { it.program } shouldContainExactly listOf(1, 2)
        }
    }
})
