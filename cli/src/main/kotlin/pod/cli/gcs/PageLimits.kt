package pod.cli.gcs

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * What one page may cost the server, so that no page (slow, stuck, hostile or merely many of
 * them) can make its memory or work grow without bound.
 */
public data class PageLimits(
    /** Events (not states) waiting for a page that reads too slowly before the oldest are dropped (the page is told how many). */
    val maxEvents: Int = 5_000,
    /** A page's requests running at once; more are answered "busy" rather than queued. */
    val maxRunning: Int = 64,
    /** The largest request a page may send (a WebSocket message): a .plan of a few thousand items fits. */
    val maxRequestBytes: Long = 4L * 1024 * 1024,
    /** How long a batch may wait for the page to read before the server gives up on the page and closes it. */
    val sendTimeout: Duration = 30.seconds,
    /** Pages open at once; one more is turned away with a close reason. */
    val maxPages: Int = 32,
) {
    init {
        require(maxEvents >= 1) { "maxEvents must be ≥ 1, was $maxEvents" }
        require(maxRunning >= 1) { "maxRunning must be ≥ 1, was $maxRunning" }
        require(maxRequestBytes >= 1024) { "maxRequestBytes must be ≥ 1024, was $maxRequestBytes" }
        require(sendTimeout.isPositive()) { "sendTimeout must be > 0, was $sendTimeout" }
        require(maxPages >= 1) { "maxPages must be ≥ 1, was $maxPages" }
    }
}
