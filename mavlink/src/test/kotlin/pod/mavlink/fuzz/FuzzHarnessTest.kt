package pod.mavlink.fuzz

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import pod.mavlink.signing.FrameSignature
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds

/** The harness catches what it is there to catch: planted escapes, broken properties, hangs and a lax or strict signing check. */
internal class FuzzHarnessTest : FunSpec({
    val corpus = FuzzCorpus(seed = 3)

    fun planted(onInput: (Int) -> Unit) = object : FuzzTarget {
        private var i = 0
        override val name = "planted"
        override fun runOne(random: Random, tally: FuzzTally) {
            tally.input(Mutation.RANDOM, random.nextBytes(4))
            onInput(i++)
        }
    }

    test("an exception out of a decoder is an escape, a failed check a violation, each kept with its input") {
        val report = FuzzRun(planted { if (it == 7) error("planted") else if (it == 9) property(false) { "broken" } }, seed = 1, inputs = 20).run()
        report.completed shouldBe 20
        report.escapes shouldBe 1
        report.violations shouldBe 1
        report.clean shouldBe false
        report.failures.map { it.index } shouldBe listOf(7L, 9L)
        report.failures[0].error shouldContain "planted"
    }

    test("an input that never finishes is reported as a hang and the run ends by itself") {
        val stuck = CountDownLatch(1)
        try {
            val report = FuzzRun(planted { if (it == 3) stuck.await(1, TimeUnit.MINUTES) }, seed = 1, inputs = 10, stuckAfter = 300.milliseconds).run()
            report.hangs shouldBe listOf(3L)
            report.completed shouldBe 3
            report.clean shouldBe false
        } finally {
            stuck.countDown()
        }
    }

    test("the same seed runs the same inputs") {
        val a = FuzzRun(DatagramDecoding(corpus), seed = 5, inputs = 2_000).run()
        val b = FuzzRun(DatagramDecoding(corpus), seed = 5, inputs = 2_000).run()
        a.clean shouldBe true
        listOf(a.bytes, a.frames, a.refused) shouldBe listOf(b.bytes, b.frames, b.refused)
        a.mutations shouldBe b.mutations
    }

    test("a signing check without replay protection is caught accepting replays") {
        val noGuard = SignedFrameReceive(corpus, "no replay guard", { key -> SignedReceive { _, wire, _ -> FrameSignature.verify(wire, key) } })
        val report = FuzzRun(noGuard, seed = 1, inputs = 2_000).run()
        report.violations shouldBeGreaterThan 0
    }

    test("a signing check that refuses everything is caught refusing fresh, authentic frames") {
        val report = FuzzRun(SignedFrameReceive(corpus, "refuses all", { SignedReceive { _, _, _ -> false } }), seed = 1, inputs = 2_000).run()
        report.violations shouldBeGreaterThan 0
    }
})
