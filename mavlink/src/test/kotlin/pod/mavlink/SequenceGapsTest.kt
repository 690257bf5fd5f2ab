package pod.mavlink

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.checkAll

class SequenceGapsTest : StringSpec({

    "frames dropped from a sequence are counted as lost, across the 255 → 0 wrap" {
        checkAll(Arb.int(0..255), Arb.list(Arb.int(0..20), 1..200)) { start, steps ->
            val gaps = SequenceGaps()
            var seq = start
            gaps.record(1, seq)
            var expectedLost = 0L
            for (skip in steps) {
                seq = (seq + skip + 1) and 0xFF
                expectedLost += skip
                gaps.record(1, seq)
            }
            gaps.received shouldBe steps.size + 1L
            gaps.lost shouldBe expectedLost
        }
    }

    "components are counted apart, and a repeated frame is not 255 lost ones" {
        val gaps = SequenceGaps()
        gaps.record(1, 10)
        gaps.record(2, 200)
        gaps.record(1, 11)
        gaps.record(2, 201)
        gaps.record(1, 11)
        gaps.lost shouldBe 0
    }

    "outgoing sequence numbers count per sender and wrap at 256" {
        val numbers = SequenceNumbers()
        (0 until 300).map { numbers.next(255, 190) }.last() shouldBe 299 % 256
        numbers.next(255, 1) shouldBe 0
    }
})
