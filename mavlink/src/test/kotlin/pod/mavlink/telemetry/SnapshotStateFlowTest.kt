package pod.mavlink.telemetry

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeSameInstanceAs
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.LinkQuality
import kotlin.time.Duration.Companion.seconds

/** The StateFlow meaning of the telemetry values built on read (SnapshotStateFlow). */
class SnapshotStateFlowTest : StringSpec({

    "a value is built once per change: reads with no change between them give the same instance" {
        val flow = PositionFlow()
        flow.value shouldBe null
        flow.update(473_977_418, 85_455_939, 488_120, 20_150, 512, -230, 15, 27_015) shouldBe true
        val first = flow.value!!
        flow.value shouldBeSameInstanceAs first
        flow.update(473_977_418, 85_455_939, 488_120, 20_150, 512, -230, 15, 27_015) // the same report again
        flow.value shouldBeSameInstanceAs first
        flow.update(473_977_419, 85_455_939, 488_120, 20_150, 512, -230, 15, 65_535)
        flow.value!!.location.latitude shouldBe 47.3977419
        flow.value!!.heading shouldBe null
        flow.update(910_000_000, 0, 0, 0, 0, 0, 0, 0) shouldBe false // beyond the pole: ignored
        flow.value!!.location.latitude shouldBe 47.3977419
    }

    "a collector gets the current value, then each different one, and never one equal to the last" {
        runTest {
            val flow = BatteryFlow()
            flow.update(80, 16_000)
            val seen = mutableListOf<Any?>()
            val job = launch { flow.collect { seen += it } }
            testScheduler.runCurrent()
            for ((remaining, voltage) in listOf(80 to 16_000, 79 to 15_900, 79 to 15_900, -1 to 65_535)) {
                flow.update(remaining, voltage)
                testScheduler.runCurrent()
            }
            seen.map { (it as pod.core.vehicle.Battery).remaining } shouldBe listOf(0.8, 0.79, null)
            job.cancel()
        }
    }

    "the last of many changes from another thread always reaches a collector" {
        runTest {
            val flow = LinkQualityFlow()
            val last = 200_000L
            val reached = async(Dispatchers.Default) { withTimeout(30.seconds) { flow.first { it.received == last } } }
            withContext(Dispatchers.Default) {
                for (n in 1..last) flow.update(n, n / 7)
            }
            reached.await() shouldBe LinkQuality(last, last / 7)
            flow.replayCache shouldBe listOf(LinkQuality(last, last / 7))
        }
    }
})
