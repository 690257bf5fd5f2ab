package pod.mavlink

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.vehicle.VehicleLost
import kotlin.time.Duration.Companion.seconds

/** The driver's wake-up ([Doorbell]) and its short poll before suspending ([HotWait]). */
class DoorbellTest : StringSpec({

    "a ring before the wait is taken once; rings do not count" {
        val bell = Doorbell()
        bell.take() shouldBe false
        bell.ring()
        bell.ring()
        bell.take() shouldBe true
        bell.take() shouldBe false
    }

    "a waiter is woken by a ring, and a ring left before await returns at once" {
        runTest {
            val bell = Doorbell()
            var woken = false
            val waiter = launch(start = CoroutineStart.UNDISPATCHED) { bell.await(); woken = true }
            woken shouldBe false
            bell.ring()
            waiter.join()
            woken shouldBe true
            bell.ring()
            bell.await() // does not suspend
            bell.take() shouldBe false
        }
    }

    "a waiter that timed out does not take the next ring away from the next wait" {
        runTest {
            val bell = Doorbell()
            withTimeoutOrNull(1.seconds) { bell.await() } shouldBe null
            bell.ring()
            bell.take() shouldBe true
        }
    }

    "closed, it wakes the waiter with the error and every later wait throws it" {
        runTest {
            val bell = Doorbell()
            val waiter = launch(start = CoroutineStart.UNDISPATCHED) { shouldThrow<VehicleLost> { bell.await() } }
            bell.close(VehicleLost(1, "test"))
            waiter.join()
            shouldThrow<VehicleLost> { bell.take() }
            shouldThrow<VehicleLost> { bell.await() }
            shouldThrow<VehicleLost> { HotWait.poll(bell, 1_000_000) }
        }
    }

    "the poll yields to the caller's other coroutines, so a ring from one of them ends it" {
        // One thread: the ring can only come if the poll lets the other coroutine run.
        runBlocking {
            val bell = Doorbell()
            launch { bell.ring() }
            HotWait.poll(bell, 10.seconds.inWholeNanoseconds) shouldBe (HotWait.MAX_SPINNERS > 0)
        }
    }

    "no budget, no poll" {
        runBlocking {
            val bell = Doorbell()
            launch { bell.ring() }
            HotWait.poll(bell, 0) shouldBe false
        }
    }
})
