package pod.mavlink.vehicle

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.test.runCurrent
import kotlinx.coroutines.test.runTest
import pod.mavlink.protocol.Step
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** A machine that answers each message and asks to be woken at the time the message names; its timer answers once and stops. */
private class Echo : VehicleMachine<Long, String> {
    val timers = ArrayList<Long>()

    override fun onMessage(message: Long, now: Long): Step<String, Nothing> = Step(listOf("ok@$now"), message)

    override fun onTimer(now: Long): Step<String, Nothing> {
        timers += now
        return Step(listOf("timer@$now"), Step.NEVER)
    }
}

/** The vehicle side's driver: replies in place, one timer at the wake time the machine asked for, on the test clock. */
@OptIn(ExperimentalCoroutinesApi::class)
class ServeTest : StringSpec({
    val ms = 1.milliseconds.inWholeNanoseconds

    "serve answers the sender in place and wakes the machine at the time its step asked, sending to the last sender" {
        runTest {
            val sent = ArrayList<Pair<String, Asker>>()
            val machine = Echo()
            val origin = testScheduler.timeSource.markNow()
            val serving = backgroundScope.serve(machine, origin) { message, to -> sent += message to to }
            serving.receive(500 * ms, Asker(255, 190))
            sent shouldBe listOf("ok@0" to Asker(255, 190))
            testScheduler.advanceTimeBy(200.milliseconds)
            serving.receive(500 * ms, Asker(254, 1)) // same wake time: the timer stays
            testScheduler.advanceTimeBy(299.milliseconds)
            runCurrent()
            machine.timers shouldBe emptyList()
            testScheduler.advanceTimeBy(2.milliseconds)
            machine.timers shouldBe listOf(500 * ms)
            sent.last() shouldBe ("timer@${500 * ms}" to Asker(254, 1))
        }
    }

    "a wake time moved later, message after message, wakes the machine once, at the last time asked" {
        runTest {
            val machine = Echo()
            val serving = backgroundScope.serve(machine, testScheduler.timeSource.markNow()) { _, _ -> }
            // As an upload moves the re-request timer with each item: 250 ms after each message.
            for (k in 0 until 10) {
                serving.receive(k * 100 * ms + 250 * ms, Asker(255, 190))
                testScheduler.advanceTimeBy(100.milliseconds)
            }
            runCurrent()
            machine.timers shouldBe emptyList()
            testScheduler.advanceTimeBy(149.milliseconds)
            runCurrent()
            machine.timers shouldBe emptyList()
            testScheduler.advanceTimeBy(2.milliseconds)
            machine.timers shouldBe listOf(1150 * ms)
        }
    }

    "a changed wake time moves the timer, and NEVER stops it" {
        runTest {
            val machine = Echo()
            val serving = backgroundScope.serve(machine, testScheduler.timeSource.markNow()) { _, _ -> }
            serving.receive(1.seconds.inWholeNanoseconds, Asker(255, 190))
            serving.receive(300 * ms, Asker(255, 190))
            testScheduler.advanceTimeBy(301.milliseconds)
            machine.timers shouldBe listOf(300 * ms)
            serving.receive(2.seconds.inWholeNanoseconds, Asker(255, 190))
            serving.receive(Step.NEVER, Asker(255, 190))
            testScheduler.advanceTimeBy(5.seconds)
            machine.timers shouldBe listOf(300 * ms)
        }
    }
})
