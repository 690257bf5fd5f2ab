package pod.cli.gcs

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.job
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * Stops what pages started in this scope (a [GcsFleet.scope]: queues being flown, surveys) and
 * waits, at most [within], until each has left its vehicle holding. Call it before closing the
 * station: the holds go out over it. Runs even when the caller is being cancelled.
 *
 * @return false when something still ran after [within] (its vehicle may not have been told to hold).
 */
internal suspend fun CoroutineScope.stopPageWork(within: Duration = 10.seconds): Boolean {
    val work = coroutineContext.job
    return withContext(NonCancellable) { withTimeoutOrNull(within) { work.cancelAndJoin() } != null }
}
