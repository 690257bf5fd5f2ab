package pod.mavlink.radio

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.ints.shouldBeInRange
import io.kotest.matchers.longs.shouldBeInRange
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.test.runTest

class RadioPacerTest : StringSpec({

    fun report(txbuf: Int) = RadioStatus(51, 68, 180, 175, txbuf, 40, 38, 0, 0)

    "off until a radio reports: sends are never delayed, however many" {
        runTest {
            val pacer = RadioPacer(RadioPacing(), testScheduler.timeSource)
            repeat(1000) { pacer.pace(280) }
            testScheduler.currentTime shouldBe 0
            pacer.active shouldBe false
        }
    }

    "once a radio reports, bytes leave at the initial rate after the first burst" {
        runTest {
            val pacing = RadioPacing(initialRate = 1000, burst = 100)
            val pacer = RadioPacer(pacing, testScheduler.timeSource)
            pacer.onReport(report(100))
            repeat(11) { pacer.pace(100) } // 1100 bytes: 100 from the bucket, 1000 at 1000 bytes/s
            testScheduler.currentTime shouldBeInRange 999L..1001L
        }
    }

    "the rate halves below 20 % free, drops a quarter below 50 %, holds in between and grows above 90 %" {
        runTest {
            val pacing = RadioPacing(initialRate = 4000, increase = 100)
            val pacer = RadioPacer(pacing, testScheduler.timeSource)
            pacer.onReport(report(100))
            pacer.rate shouldBe 4000
            pacer.onReport(report(10)); pacer.rate shouldBe 2000
            pacer.onReport(report(40)); pacer.rate shouldBe 1500
            pacer.onReport(report(70)); pacer.rate shouldBe 1500
            pacer.onReport(report(92)); pacer.rate shouldBe 1600
            pacer.onReport(report(100)); pacer.rate shouldBe 1800
        }
    }

    "the rate stays within its bounds, whatever the reports say" {
        runTest {
            val pacing = RadioPacing(initialRate = 1000, minRate = 500, maxRate = 1200, increase = 1000)
            val pacer = RadioPacer(pacing, testScheduler.timeSource)
            pacer.onReport(report(100))
            repeat(5) { pacer.onReport(report(0)) }
            pacer.rate shouldBe 500
            repeat(5) { pacer.onReport(report(100)) }
            pacer.rate shouldBeInRange 1200..1200
        }
    }

    "pacing turned off still records the radio's report" {
        runTest {
            val pacer = RadioPacer(RadioPacing.Off, testScheduler.timeSource)
            pacer.onReport(report(30))
            pacer.status.value?.txbuf shouldBe 30
            pacer.active shouldBe false
        }
    }

    "impossible settings are refused with the argument's name" {
        shouldThrow<IllegalArgumentException> { RadioPacing(initialRate = 10, minRate = 100) }.message shouldBe "initialRate must be in 100..11520 bytes/s, was 10"
        shouldThrow<IllegalArgumentException> { RadioPacing(lowBelow = 95, roomyAbove = 90) }
    }
})
