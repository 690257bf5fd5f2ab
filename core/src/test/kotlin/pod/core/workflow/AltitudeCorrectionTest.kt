package pod.core.workflow

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.double
import io.kotest.property.checkAll
import pod.core.units.m

class AltitudeCorrectionTest : StringSpec({

    "readings within the tolerance, and a single outlier, change nothing" {
        val c = AltitudeCorrection(target = 20.m, tolerance = 2.m, minimum = 5.m, maximum = 120.m)
        c.reading(21.5.m, 20.m) shouldBe null
        c.reading(10.m, 20.m) shouldBe null
        c.reading(20.m, 20.m) shouldBe null // the run of off readings starts again
        c.reading(10.m, 20.m) shouldBe null
        c.reading(10.m, 20.m) shouldBe null
        c.reading(10.m, 20.m)!!.meters shouldBe (10.0 plusOrMinus 1e-9) // a hill 10 m high: climb 10 m
    }

    "a correction puts the vehicle back at its target height above the ground, within the bounds" {
        val bound = Arb.double(0.0, 200.0, includeNaNs = false)
        checkAll(PropTestConfig(iterations = 500, seed = 15), bound, bound, Arb.double(5.0, 150.0, includeNaNs = false)) { measured, ground, altitude ->
            val c = AltitudeCorrection(target = 25.m, tolerance = 1.m, minimum = 10.m, maximum = 100.m, confirmations = 1)
            val change = c.reading(measured.m, altitude.m)
            val off = kotlin.math.abs(25.0 - measured)
            if (off <= 1.0) {
                change shouldBe null
            } else if (change != null) {
                val corrected = altitude + change.meters
                (corrected in 10.0 - 1e-9..100.0 + 1e-9) shouldBe true
                // Unclamped, the new height above this ground is the target.
                if (altitude + (25.0 - measured) in 10.0..100.0) (measured + change.meters) shouldBe (25.0 plusOrMinus 1e-9)
            } else {
                // Only a bound can cancel a due correction: the vehicle is already at it.
                (kotlin.math.abs(altitude - 10.0) < 1e-6 || kotlin.math.abs(altitude - 100.0) < 1e-6 || altitude < 10.0 || altitude > 100.0) shouldBe true
            }
        }
    }

    "bad settings fail when built, naming them" {
        shouldThrow<IllegalArgumentException> { AltitudeCorrection(0.m, 1.m, 5.m, 50.m) }.message shouldContain "target"
        shouldThrow<IllegalArgumentException> { AltitudeCorrection(20.m, 0.m, 5.m, 50.m) }.message shouldContain "tolerance"
        shouldThrow<IllegalArgumentException> { AltitudeCorrection(20.m, 1.m, 60.m, 50.m) }.message shouldContain "minimum"
    }
})
