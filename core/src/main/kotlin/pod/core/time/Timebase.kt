package pod.core.time

import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.Dispatchers
import kotlin.time.TimeSource

/**
 * The clock a part of Pod reads and the dispatcher whose `delay`s follow that clock, as one value,
 * so the two cannot disagree.
 *
 * [System] is the wall clock on [Dispatchers.Default]. A test passes kotlinx-coroutines-test's
 * scheduler instead (`Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))`):
 * every reading and every delay of a ground station and its simulated vehicles then runs in
 * virtual time, deterministic, with no real-time deadline.
 */
public class Timebase(
    /** Every time reading goes through this clock. */
    public val clock: TimeSource.WithComparableMarks,
    /** Every coroutine runs here, so every `delay` and timeout follows [clock]. */
    public val dispatcher: CoroutineDispatcher,
) {
    override fun toString(): String = if (this === System) "Timebase.System" else "Timebase($clock, $dispatcher)"

    /** The timebase of a real run; tests make their own from a test scheduler. */
    public companion object {
        /** The monotonic wall clock and [Dispatchers.Default]. */
        public val System: Timebase = Timebase(TimeSource.Monotonic, Dispatchers.Default)
    }
}
