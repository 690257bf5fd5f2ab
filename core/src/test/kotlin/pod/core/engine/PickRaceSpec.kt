package pod.core.engine

import pod.core.time.virtualTimebase
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withContext
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds

class PickRaceSpec : FunSpec({
    test("releasing a vehicle twice fails the second time with NotPicked and announces one release") {
        runTest {
            val fleet = FakeFleet(2)
            val engine = Engine(fleet, EngineConfig(timebase = virtualTimebase()))
            val released = mutableListOf<EngineEvent.Released>()
            val collector = launch { engine.events.collect { if (it is EngineEvent.Released) released += it } }
            testScheduler.runCurrent()
            engine.run {
                val v = pick(PickRequest(count = 1))
                release(v)
                val second = runCatching { release(v) }.exceptionOrNull()
                withClue("second release") { (second is NotPicked) shouldBe true }
                picked.value.shouldBeEmpty()
            }
            testScheduler.runCurrent()
            collector.cancel()
            released.map { it.vehicles } shouldBe listOf(listOf(1))
        }
    }

    test("programs picking, releasing twice at once and timing out on many threads never hold one vehicle together") {
        val fleet = FakeFleet(3)
        val engine = Engine(fleet)
        // Vehicle id → how many programs believe they hold it; must never exceed 1.
        val holders = MutableStateFlow<Map<Int, Int>>(emptyMap())
        val worst = MutableStateFlow(0)
        withContext(Dispatchers.Default) {
            List(6) { p ->
                async {
                    val random = Random(p)
                    repeat(300) {
                        engine.run {
                            val got = runCatching { pick(PickRequest(count = random.nextInt(1, 3), timeout = random.nextInt(1, 3).milliseconds)) }.getOrNull()
                                ?: return@run
                            holders.update { h -> h + got.ids.associateWith { (h[it] ?: 0) + 1 } }
                            worst.update { w -> maxOf(w, holders.value.values.max()) }
                            holders.update { h -> h + got.ids.associateWith { h.getValue(it) - 1 } }
                            // Two releases of the same vehicles at once: exactly one may succeed.
                            val outcomes = List(2) { async(Dispatchers.Default) { runCatching { release(got) }.isSuccess } }.awaitAll()
                            withClue("concurrent releases that succeeded") { outcomes.count { it } shouldBe 1 }
                        }
                    }
                }
            }.awaitAll()
        }
        withClue("most programs that believed they held one vehicle at once") { worst.value shouldBe 1 }
        engine.pickedByAny.value.shouldBeEmpty()
        engine.run { pick(PickRequest(count = 3, timeout = 1.milliseconds)).size shouldBe 3 }
    }
})
