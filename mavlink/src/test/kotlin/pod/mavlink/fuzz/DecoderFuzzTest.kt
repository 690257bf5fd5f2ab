package pod.mavlink.fuzz

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.shouldBe

/**
 * CI's fuzz run: 100,000 seeded mutated inputs per decoder (the soak run, `bench/fuzz.sh`, runs 10
 * million). Every input must run with no escaped exception, no broken property and no hang; and the
 * run must have exercised what it claims (frames delivered, inputs refused, every mutation used).
 */
internal class DecoderFuzzTest : FunSpec({
    val corpus = FuzzCorpus(seed = 27)

    for (target in DecoderFuzzTargets.all(corpus)) {
        test("${target.name}: 100k mutated inputs, no escape, no broken property, no hang") {
            val report = FuzzRun(target, seed = 20261128, inputs = INPUTS).run()
            withClue(report.toString()) {
                report.completed shouldBe INPUTS
                report.hangs shouldBe emptyList()
                report.escapes shouldBe 0
                report.violations shouldBe 0
                report.frames shouldBeGreaterThan INPUTS / 10
                report.refused + report.frames shouldBeGreaterThan 0
            }
        }
    }
}) {
    private companion object {
        const val INPUTS = 100_000L
    }
}
