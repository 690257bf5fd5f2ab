package pod.mavlink

import kotlinx.coroutines.yield
import java.util.concurrent.atomic.AtomicInteger

/**
 * A short wait for an answer expected within a round trip on a quick link, without parking the
 * caller's thread.
 *
 * A reply is taken in on the link's receive thread and fed to the exchange there (see [run]); a
 * caller suspended until then is resumed through its dispatcher, which on an idle machine means
 * waking a parked thread: on a 2-core KVM guest that one wake-up was 0.14 ms of a 0.55 ms command
 * round trip (BENCHMARKS.md, issue 13), where pymavlink's loop blocks in `select` on the socket
 * itself and pays no second wake-up. So for about one expected round trip the caller polls its
 * [Doorbell] instead of suspending, yielding to its dispatcher between polls (the other coroutines
 * there keep running: several commands at once all go out while one waits) and to the operating
 * system every few polls (the receive thread or the vehicle may need this core). When the budget
 * runs out the caller suspends as before.
 *
 * At most [MAX_SPINNERS] callers poll at once in the process, one fewer than the cores (none on one
 * core), so that the receive thread always has a core; the others suspend at once. The budget comes
 * from the exchange's round-trip estimate and is 0 on a slow or unsteady link: a loaded machine,
 * whose round trips swing by milliseconds, stops polling by itself.
 */
internal object HotWait {
    /** Callers polling at once: one fewer than the cores (none on one core). */
    val MAX_SPINNERS: Int = Runtime.getRuntime().availableProcessors() - 1

    /** Longest poll, whatever the estimate: beyond this a suspension's wake-up is the smaller cost. */
    const val MAX_BUDGET_NANOS: Long = 2_000_000L

    /** Polls between two yields to the operating system. */
    private const val OS_YIELD_EVERY = 16

    private val spinners = AtomicInteger()

    /**
     * Polls [bell] for up to [budgetNanos] (real time), yielding between polls: true once it rang,
     * false when the budget ran out or too many callers poll already. Throws what a closed [bell]
     * throws.
     */
    suspend fun poll(bell: Doorbell, budgetNanos: Long): Boolean {
        if (budgetNanos <= 0) return false
        if (spinners.incrementAndGet() > MAX_SPINNERS) {
            spinners.decrementAndGet()
            return false
        }
        try {
            val until = System.nanoTime() + budgetNanos.coerceAtMost(MAX_BUDGET_NANOS)
            var polls = 0
            while (true) {
                if (bell.take()) return true
                if (System.nanoTime() - until >= 0) return false
                if (++polls % OS_YIELD_EVERY == 0) Thread.yield()
                yield()
            }
        } finally {
            spinners.decrementAndGet()
        }
    }
}
