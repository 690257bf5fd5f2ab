package pod.core.queue

import pod.core.time.virtualTimebase
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.runCurrent
import kotlinx.coroutines.test.runTest
import pod.core.units.m
import kotlin.time.Duration.Companion.seconds

class MissionQueueTest : StringSpec({

    fun goto(n: Int) = QueueElement(QueuePattern.Goto(at(n.m, 0.m)))

    "the four insertion modes, next and arrivals give Paparazzi's order, and events say why each element ended" {
        runTest {
            val queue = MissionQueue(virtualTimebase())
            val events = mutableListOf<QueueEvent>()
            val collecting = launch { queue.events.toList(events) }
            runCurrent()
            val a = queue.append(goto(1))
            val b = queue.append(goto(2))
            val c = queue.append(goto(3))
            val circle = queue.prepend(QueueElement(QueuePattern.Circle(at(0.m, 0.m), 20.m), duration = 60.seconds))
            queue.state.value.entries shouldBe listOf(circle, a, b, c)
            queue.status.value.remaining shouldBe 60.seconds
            val segment = queue.replaceCurrent(QueueElement(QueuePattern.Segment(at(0.m, 0.m), at(50.m, 0.m))))
            queue.state.value.entries shouldBe listOf(segment, a, b, c)
            queue.arrived(a.id) // late or early: a is not current, nothing happens
            queue.state.value.current shouldBe segment
            queue.arrived(segment.id)
            queue.state.value.current shouldBe a
            val path = queue.replaceAll(QueueElement(QueuePattern.Path(List(5) { at((it * 10).m, 0.m) })))
            queue.state.value.entries shouldBe listOf(path)
            queue.next() shouldBe path
            queue.next() shouldBe null
            runCurrent()
            collecting.cancel()
            events.map { it.describe() } shouldBe listOf(
                "start ${a.id}",
                "end ${a.id} PREEMPTED", "start ${circle.id}",
                "end ${circle.id} REPLACED", "start ${segment.id}",
                "end ${segment.id} ARRIVED", "start ${a.id}",
                "end ${a.id} REPLACED", "start ${path.id}",
                "end ${path.id} SKIPPED", "empty",
            )
        }
    }

    "a duration runs out on the queue's clock and the next element starts with its whole duration" {
        runTest {
            val queue = MissionQueue(virtualTimebase())
            val circle = queue.append(QueueElement(QueuePattern.Circle(at(0.m, 0.m), -15.m), duration = 10.seconds))
            val hold = queue.append(QueueElement(QueuePattern.Hold, duration = 4.seconds))
            testScheduler.advanceTimeBy(6.seconds)
            queue.expire()
            queue.status.value shouldBe QueueStatus(circle, 4.seconds, listOf(hold))
            testScheduler.advanceTimeBy(4.seconds)
            queue.expire()
            queue.status.value shouldBe QueueStatus(hold, 4.seconds, emptyList())
            testScheduler.advanceTimeBy(5.seconds)
            queue.expire()
            queue.status.value shouldBe QueueStatus.EMPTY
        }
    }

    "a prepended element suspends the current one, which resumes with its whole duration" {
        runTest {
            val queue = MissionQueue(virtualTimebase())
            val circle = queue.append(QueueElement(QueuePattern.Circle(at(0.m, 0.m), 30.m), duration = 20.seconds))
            testScheduler.advanceTimeBy(15.seconds)
            val goto = queue.prepend(goto(5))
            queue.arrived(goto.id)
            queue.status.value shouldBe QueueStatus(circle, 20.seconds, emptyList())
        }
    }

    "a queue for a simulator running five times faster than its clock counts durations in vehicle time" {
        runTest {
            val queue = MissionQueue(virtualTimebase(), timeScale = 5.0)
            val hold = queue.append(QueueElement(QueuePattern.Hold, duration = 60.seconds))
            testScheduler.advanceTimeBy(11.seconds)
            queue.expire()
            queue.status.value shouldBe QueueStatus(hold, 5.seconds, emptyList())
            testScheduler.advanceTimeBy(1.seconds)
            queue.expire()
            queue.status.value shouldBe QueueStatus.EMPTY
        }
    }

    "zero and negative durations mean none, as in Paparazzi" {
        QueueElement(QueuePattern.Hold, duration = 0.seconds).limit shouldBe null
        QueueElement(QueuePattern.Hold, duration = (-3).seconds).limit shouldBe null
        runTest {
            val queue = MissionQueue(virtualTimebase())
            queue.append(QueueElement(QueuePattern.Circle(at(0.m, 0.m), 30.m), duration = 0.seconds))
            testScheduler.advanceTimeBy(3600.seconds)
            queue.expire()
            queue.status.value.remaining shouldBe null
            queue.state.value.isEmpty shouldBe false
        }
    }

    "one queue is flown by one flight at a time" {
        val queue = MissionQueue()
        val release = queue.claim("copter-1")
        shouldThrow<QueueBusy> { queue.claim("copter-2") }.message shouldContain "copter-1"
        release()
        queue.claim("copter-2")
        queue.flyer.value shouldBe "copter-2"
    }

    "bad elements fail when built, naming the argument" {
        shouldThrow<IllegalArgumentException> { QueuePattern.Circle(at(0.m, 0.m), 0.m) }.message shouldContain "radius"
        shouldThrow<IllegalArgumentException> { QueuePattern.Path(emptyList()) }.message shouldContain "at least one point"
        shouldThrow<IllegalArgumentException> { QueueElement(QueuePattern.Hold, altitude = (-5).m) }.message shouldContain "altitude"
        shouldThrow<IllegalArgumentException> { at(Double.NaN.m, 0.m) }.message shouldContain "finite"
        shouldThrow<IllegalArgumentException> { QueuePattern.Survey(at(0.m, 0.m), 100.m, 50.m, 0.m) }.message shouldContain "spacing"
    }
}) {
    private companion object {
        fun QueueEvent.describe(): String = when (this) {
            is QueueEvent.Started -> "start ${entry.id}"
            is QueueEvent.Ended -> "end ${entry.id} $reason"
            is QueueEvent.Emptied -> "empty"
        }
    }
}
