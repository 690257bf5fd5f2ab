package pod.core.units

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.Duration.Companion.seconds

class DurationsTest : StringSpec({
    "durations read rounded to what matters at their size, never in nanoseconds" {
        (10.seconds + 1_305_558.nanoseconds).toReadable() shouldBe "10.0 s"
        400.milliseconds.toReadable() shouldBe "0.4 s"
        59.94.seconds.toReadable() shouldBe "59.9 s"
        90.seconds.toReadable() shouldBe "1 min 30 s"
        2.minutes.toReadable() shouldBe "2 min"
        (2.hours + 5.minutes).toReadable() shouldBe "2 h 5 min"
        Duration.INFINITE.toReadable() shouldBe "forever"
        (-1).seconds.toReadable() shouldBe "-1.0 s"
    }
})
