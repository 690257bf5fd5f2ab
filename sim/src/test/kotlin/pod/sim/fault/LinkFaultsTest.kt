package pod.sim.fault

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.booleans.shouldBeFalse
import io.kotest.matchers.booleans.shouldBeTrue
import io.kotest.matchers.shouldBe
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds

class LinkFaultsTest : StringSpec({

    "a probability outside 0..1 is refused with its name, the range and the value" {
        shouldThrow<IllegalArgumentException> { LinkFaults(drop = 1.5) }.message shouldBe "drop must be in 0..1, was 1.5"
        shouldThrow<IllegalArgumentException> { LinkFaults(duplicate = -0.1) }.message shouldBe "duplicate must be in 0..1, was -0.1"
        shouldThrow<IllegalArgumentException> { LinkFaults(reorder = 2.0) }.message shouldBe "reorder must be in 0..1, was 2.0"
        shouldThrow<IllegalArgumentException> { LinkFaults(corrupt = Double.NaN) }.message shouldBe "corrupt must be in 0..1, was NaN"
    }

    "negative or infinite times and a reorder depth below 1 are refused" {
        shouldThrow<IllegalArgumentException> { LinkFaults(delay = (-1).milliseconds) }.message shouldBe
            "delay must be ≥ 0 and finite, was -1ms"
        shouldThrow<IllegalArgumentException> { LinkFaults(jitter = Duration.INFINITE) }.message shouldBe
            "jitter must be ≥ 0 and finite, was Infinity"
        shouldThrow<IllegalArgumentException> { LinkFaults(maxHold = Duration.ZERO) }.message shouldBe
            "maxHold must be > 0 and finite, was 0s"
        shouldThrow<IllegalArgumentException> { LinkFaults(reorderDepth = 0) }.message shouldBe "reorderDepth must be ≥ 1, was 0"
    }

    "the edges of every range are accepted, and copy validates too" {
        val edges = LinkFaults(drop = 1.0, duplicate = 0.0, reorder = 1.0, corrupt = 1.0, reorderDepth = 1, delay = Duration.ZERO)
        edges.isNone.shouldBeFalse()
        LinkFaults.None.isNone.shouldBeTrue()
        shouldThrow<IllegalArgumentException> { edges.copy(drop = 1.01) }.message shouldBe "drop must be in 0..1, was 1.01"
    }
})
