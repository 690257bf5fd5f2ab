package pod.core.time

import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.TestScope

/** This test's virtual clock and a dispatcher on its scheduler, as one [Timebase]. */
internal fun TestScope.virtualTimebase(): Timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
