package pod.sim

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** A simulated vehicle's streams follow its own clock, as ArduPilot SITL's do under a speed-up, within bounds. */
class SimSendRateTest : StringSpec({
    "at time scale 1 a stream keeps the real firmware's wall-clock rate" {
        StreamScheduler.sendPeriod(1.0, 1.0) shouldBe 1.seconds
        StreamScheduler.sendPeriod(4.0, 1.0) shouldBe 250.milliseconds
        StreamScheduler.sendPeriod(100.0, 1.0) shouldBe 10.milliseconds // asked for, not capped
    }

    "at time scale 40 a 1 Hz heartbeat comes every 25 ms of wall time, a 2 Hz stream every 12.5 ms capped to 20 ms" {
        StreamScheduler.sendPeriod(1.0, 40.0) shouldBe 25.milliseconds
        StreamScheduler.sendPeriod(2.0, 40.0) shouldBe 20.milliseconds
        StreamScheduler.sendPeriod(0.2, 40.0) shouldBe 125.milliseconds
    }

    "a vehicle slower than real time keeps real-time rates, so a ground station never takes it for lost" {
        StreamScheduler.sendPeriod(1.0, 0.25) shouldBe 1.seconds
    }

    "no stream goes faster than 50 a second of wall time, however fast the clock" {
        StreamScheduler.sendPeriod(1.0, 1000.0) shouldBe 20.milliseconds
        StreamScheduler.sendPeriod(50.0, 1000.0) shouldBe 20.milliseconds
    }
})
