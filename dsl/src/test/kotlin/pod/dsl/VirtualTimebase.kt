package pod.dsl

import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.TestScope
import pod.core.time.Timebase

/** This test's virtual clock and a dispatcher on its scheduler, as one [Timebase] (core's tests have their own). */
internal fun TestScope.virtualTimebase(): Timebase = Timebase(testScheduler.timeSource, StandardTestDispatcher(testScheduler))
