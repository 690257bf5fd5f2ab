package pod.core.units

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.arbitrary.double
import io.kotest.property.checkAll
import kotlin.math.hypot

class LocationTest : StringSpec({

    "an offset of a few hundred metres is that far away on the great circle, within 0.5%" {
        checkAll(
            Arb.double(-70.0, 70.0, includeNaNs = false),
            Arb.double(-179.0, 179.0, includeNaNs = false),
            Arb.double(-500.0, 500.0, includeNaNs = false),
            Arb.double(-500.0, 500.0, includeNaNs = false),
        ) { lat, lon, north, east ->
            val from = Location(lat, lon)
            val to = from.offset(north.m, east.m, 10.m)
            val expected = hypot(north, east)
            from.distanceTo(to).meters shouldBe (expected plusOrMinus (expected * 0.005 + 0.01))
            to.altitude shouldBe 10.m
        }
    }

    "one degree of latitude is about 111.2 km" {
        Location(0.0, 0.0).distanceTo(Location(1.0, 0.0)).meters shouldBe (111_195.0 plusOrMinus 5.0)
    }

    "coordinates out of range are refused with the value" {
        shouldThrow<IllegalArgumentException> { Location(91.0, 0.0) }.message!! shouldContain "latitude must be in -90..90, was 91.0"
        shouldThrow<IllegalArgumentException> { Location(0.0, -180.5) }.message!! shouldContain "longitude must be in -180..180, was -180.5"
    }
})
