package pod.mavlink.protocol

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.test.runTest
import pod.core.PodException
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

private class Refused(val why: String) : PodException("refused: $why")

private class GaveUp(val reason: String) : PodException("gave up waiting for $reason")

/** A policy retrying [Refused] "busy" every [pause] for [window], giving up with [GaveUp]. */
private fun policy(pause: Duration, window: Duration, lastPause: RetryPolicy.LastPause) = RetryPolicy(
    pause, window, lastPause,
    retried = { e -> (e as? Refused)?.why?.takeIf { it == "busy" } },
    giveUp = { _, reason -> GaveUp(reason) },
)

class RetryPolicyTest : StringSpec({

    "a refusal that clears is retried at the pause until the attempt succeeds, saying why before each pause" {
        runTest {
            val clock = testScheduler.timeSource
            val start = clock.markNow()
            val tries = ArrayList<Duration>()
            val waits = ArrayList<String>()
            val result = policy(1.seconds, 10.seconds, RetryPolicy.LastPause.WHOLE).run(clock, start, onWait = { waits += it }) {
                tries += start.elapsedNow()
                if (tries.size < 3) throw Refused("busy") else "done"
            }
            result shouldBe "done"
            tries shouldBe listOf(Duration.ZERO, 1.seconds, 2.seconds)
            waits shouldBe listOf("busy", "busy")
        }
    }

    "whole pauses: no attempt is begun after a pause that would end past the window, and the give-up is typed" {
        runTest {
            val clock = testScheduler.timeSource
            val start = clock.markNow()
            var tries = 0
            val error = shouldThrow<GaveUp> {
                policy(1.seconds, 2500.milliseconds, RetryPolicy.LastPause.WHOLE).run(clock, start) {
                    tries++
                    throw Refused("busy")
                }
            }
            error.reason shouldBe "busy"
            tries shouldBe 3 // at 0, 1 and 2 s; a fourth at 3 s would be past 2.5 s
            start.elapsedNow() shouldBe 2.seconds
        }
    }

    "cut pauses: the last pause ends with the window and one more attempt follows it" {
        runTest {
            val clock = testScheduler.timeSource
            val start = clock.markNow()
            val tries = ArrayList<Duration>()
            shouldThrow<GaveUp> {
                policy(1.seconds, 2500.milliseconds, RetryPolicy.LastPause.CUT_TO_WINDOW).run(clock, start) {
                    tries += start.elapsedNow()
                    throw Refused("busy")
                }
            }
            tries shouldBe listOf(Duration.ZERO, 1.seconds, 2.seconds, 2500.milliseconds)
        }
    }

    "without a start the window opens at the first refusal" {
        runTest {
            val clock = testScheduler.timeSource
            val start = clock.markNow()
            val tries = ArrayList<Duration>()
            shouldThrow<GaveUp> {
                policy(500.milliseconds, 1.seconds, RetryPolicy.LastPause.CUT_TO_WINDOW).run(clock, from = null) {
                    tries += start.elapsedNow()
                    // The first refusal comes 3 s after the call: the window is counted from then.
                    if (tries.size == 1) kotlinx.coroutines.delay(3.seconds)
                    throw Refused("busy")
                }
            }
            tries shouldBe listOf(Duration.ZERO, 3500.milliseconds, 4.seconds)
        }
    }

    "a refusal that waiting will not clear, and any other error, is thrown at once as it is" {
        runTest {
            val clock = testScheduler.timeSource
            var tries = 0
            shouldThrow<Refused> {
                policy(1.seconds, 10.seconds, RetryPolicy.LastPause.WHOLE).run(clock, clock.markNow()) {
                    tries++
                    throw Refused("battery")
                }
            }.why shouldBe "battery"
            shouldThrow<IllegalStateException> {
                policy(1.seconds, 10.seconds, RetryPolicy.LastPause.WHOLE).run(clock, clock.markNow()) {
                    tries++
                    error("broken")
                }
            }
            tries shouldBe 2
        }
    }

    "by default the give-up is the last refusal itself" {
        runTest {
            val clock = testScheduler.timeSource
            val plain = RetryPolicy(100.milliseconds, Duration.ZERO, RetryPolicy.LastPause.CUT_TO_WINDOW, retried = { (it as? Refused)?.why })
            shouldThrow<Refused> { plain.run(clock, clock.markNow()) { throw Refused("busy") } }.why shouldBe "busy"
        }
    }
})
