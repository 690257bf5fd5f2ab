package pod.mavlink.protocol

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.delay
import kotlin.time.Duration
import kotlin.time.TimeMark
import kotlin.time.TimeSource

/**
 * How Pod tries again an operation that a vehicle refused for a reason that clears by waiting: an
 * upload refused NO_SPACE while a freshly booted ArduPilot starts its mission storage, a transfer
 * refused DENIED while ArduPilot still holds an abandoned upload, an arm or mode change refused
 * while the estimator initialises. One shape for all of them, so that each says only what differs:
 * - what is retried: [retried] names the reason to wait for a refusal, or null for one that
 *   waiting will not clear (thrown as it is);
 * - how often: [pause] between a refusal and the next attempt;
 * - how long: [window], counted from a mark the caller gives (the vehicle's appearance, the first
 *   attempt) or, when it gives none, from the first refusal; [lastPause] says how the end of the
 *   window is met;
 * - what it throws when it gives up: [giveUp] turns the last refusal and its reason into a typed
 *   error ([pod.core.PodException]), the refusal itself by default.
 *
 * Time is read on the station's clock (its Timebase's) and the pauses are the coroutine's `delay`s,
 * so a virtual-time test runs the whole wait in no real time.
 */
internal class RetryPolicy(
    /** Between a refusal and the next attempt. */
    val pause: Duration,
    /** How long refusals are tried again. */
    val window: Duration,
    /** How the last pause meets the end of [window]. */
    val lastPause: LastPause,
    /** The reason to wait for a refusal, or null when it is not retried. */
    val retried: (Exception) -> String?,
    /** The error thrown when the window is over, from the last refusal and its reason. */
    val giveUp: (refusal: Exception, reason: String) -> Exception = { refusal, _ -> refusal },
) {
    /** How the last pause meets the end of the window. */
    enum class LastPause {
        /** The last pause is cut short to end with the window, and one more attempt follows it. */
        CUT_TO_WINDOW,

        /** Only whole pauses: no pause that would end past the window is begun. */
        WHOLE,
    }

    /**
     * Runs [attempt] until it succeeds, is refused for a reason not [retried], or the window is
     * over ([giveUp]). [from] opens the window (null: the first refusal does); [onWait] is told the
     * reason before each pause.
     */
    suspend fun <T> run(clock: TimeSource, from: TimeMark?, onWait: (reason: String) -> Unit = {}, attempt: suspend () -> T): T {
        var opened = from
        while (true) {
            try {
                return attempt()
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                val reason = retried(e) ?: throw e
                val start = opened ?: clock.markNow().also { opened = it }
                val wait = nextPause(start) ?: throw giveUp(e, reason)
                onWait(reason)
                delay(wait)
            }
        }
    }

    /** The pause before the next attempt, or null when the window opened at [start] is over. */
    private fun nextPause(start: TimeMark): Duration? = when (lastPause) {
        LastPause.CUT_TO_WINDOW -> (window - start.elapsedNow()).takeIf { it > Duration.ZERO }?.let { minOf(pause, it) }
        LastPause.WHOLE -> pause.takeUnless { start.elapsedNow() + pause > window }
    }
}
