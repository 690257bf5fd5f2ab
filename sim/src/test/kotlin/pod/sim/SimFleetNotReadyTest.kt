package pod.sim

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.runTest
import pod.core.time.Timebase
import pod.mavlink.link.MemoryNetwork
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/** A fleet that is not ready in time fails with a typed error naming what was not heard, not a bare timeout. */
class SimFleetNotReadyTest : StringSpec({
    "a vehicle whose GPS needs longer than the ready timeout fails the start with SimFleetNotReady naming it" {
        runTest(timeout = 1.minutes) {
            val timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
            val network = MemoryNetwork(backgroundScope, timebase)
            val failure = shouldThrow<SimFleetNotReady> {
                SimPlatform.start(
                    backgroundScope, listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4), timeScale = 1.0, readyTimeout = 10.seconds,
                    timebase = timebase, openLink = LinkOpener.memory(network),
                ) { if (it.systemId == 2) it.copy(positionReadyAfter = 5.minutes) else it }
            }
            failure.waiting.keys shouldBe setOf(2)
            failure.timeout shouldBe 10.seconds
            failure.message shouldContain "vehicle 2"
        }
    }
})
