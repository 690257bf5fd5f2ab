package pod.cli.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withContext
import kotlin.time.Duration.Companion.seconds

/** Stopping the pages' work waits for it to hold its vehicles, within a bound (virtual time). */
class PageWorkTest : StringSpec({

    "stopping waits until each piece of work has told its vehicle to hold, then says it all stopped" {
        runTest {
            val pages = CoroutineScope(coroutineContext + SupervisorJob())
            val held = mutableListOf<Int>()
            for (sysid in 1..3) {
                pages.launch {
                    try {
                        awaitCancellation()
                    } finally {
                        // The hold is a command round trip: it takes time after the cancellation.
                        withContext(NonCancellable) {
                            delay(sysid.seconds)
                            held += sysid
                        }
                    }
                }
            }
            testScheduler.runCurrent()
            pages.stopPageWork(within = 10.seconds) shouldBe true
            held.sorted() shouldBe listOf(1, 2, 3)
        }
    }

    "work that does not stop within the bound is given up on and reported, rather than hanging the shutdown" {
        runTest {
            val pages = CoroutineScope(coroutineContext + SupervisorJob())
            pages.launch {
                try {
                    awaitCancellation()
                } finally {
                    withContext(NonCancellable) { delay(60.seconds) }
                }
            }
            testScheduler.runCurrent()
            val start = testScheduler.currentTime
            pages.stopPageWork(within = 10.seconds) shouldBe false
            (testScheduler.currentTime - start) shouldBe 10_000L
        }
    }
})
