package pod.core.engine

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.checkAll
import kotlinx.coroutines.test.runTest

/**
 * Random task trees (depth ≤ 4, every node kind, shared and failing vehicles) run as programs on
 * the fake fleet in virtual time — sometimes two programs at once on one engine, some cancelled,
 * some losing a vehicle (for good or for a few seconds) at a random moment. Every case must keep
 * the engine's promises: (a) no vehicle flies two missions at once, (b) nothing is held or airborne
 * after the program, (c) interrupted flights are made safe before the program returns, (d) the
 * program ends within a bound computed from the tree, (e) task events nest.
 * kotest prints the failing case and its seed; -Dpod.engine.seed=N and -Dpod.engine.iterations=N
 * run others.
 */
class EnginePropertySpec : FunSpec({
    val seed = System.getProperty("pod.engine.seed")?.toLong() ?: 20261122L
    val iterations = System.getProperty("pod.engine.iterations")?.toInt() ?: 400
    val scenarios: Arb<Scenario> = arbitrary { rs -> Scenario.generate(rs.random) }

    test("random task trees, cancelled or losing a vehicle at random times, keep every engine invariant") {
        val outcomes = mutableMapOf<String, Int>()
        val failures = mutableMapOf<String, Int>()
        checkAll(PropTestConfig(seed = seed, iterations = iterations), scenarios) { scenario ->
            runTest {
                val result = runAndCheck(scenario)
                for (outcome in result.outcomes.values) {
                    val kind = if (outcome is Outcome.Failed) "failed:" + outcome.error::class.simpleName else outcome.toString()
                    outcomes.merge(kind, 1, Int::plus)
                }
                result.events.filterIsInstance<EngineEvent.TaskFailed>().forEach { failures.merge(it.error::class.simpleName.orEmpty(), 1, Int::plus) }
            }
        }
        println("engine property programs by outcome (seed $seed): $outcomes; task failures by error: $failures")
        withClue("the generator must reach every way a program ends: $outcomes") {
            for (kind in listOf("Completed", "Cancelled", "failed:VehicleBusy", "failed:IllegalStateException", "failed:VehicleLost")) {
                (outcomes[kind] ?: 0) shouldBeGreaterThan 0
            }
        }
    }
})
