package pod.cli.gcs

import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.withTimeoutOrNull
import pod.cli.json.Event
import pod.cli.json.GcsBatch
import kotlin.time.Duration

/**
 * Sends a page what its [page] feed gathered: at most one [GcsBatch] per [tick] (none when nothing
 * changed), numbered from 1. While a send waits for a page that reads slowly, the feed goes on
 * gathering, states conflated to the latest and events up to its bound, so the next batch carries
 * everything the page still needs; a send that waits longer than [sendTimeout] ends the page
 * ([PageStalled]) rather than hold its resources for ever.
 *
 * A page that says which batches it has taken in ([drawn]: the page's `{"drawn": seq}`) is paced
 * by them from its first such word on: at most [window] batches are on their way to it at once, so
 * a page slower than the tick (a weak laptop, 250 vehicles) gets fewer, fresher batches instead of
 * a backlog in its browser that the server could no longer conflate. A page that never says is
 * sent one batch per tick as before. Waiting for a page's word has no deadline of its own (a
 * hidden tab may take a minute): what waits meanwhile is bounded by the feed.
 */
internal class PageBatcher(
    private val page: PageFeed,
    private val tick: Duration,
    private val sendTimeout: Duration,
    /** Batches a pacing page may have unacknowledged. */
    private val window: Int = 2,
    private val send: suspend (Event) -> Unit,
) {
    init {
        require(window >= 1) { "window must be ≥ 1, was $window" }
    }

    private val drawnUpTo = MutableStateFlow<Long?>(null)

    /** The page has taken in every batch up to [seq]. */
    fun drawn(seq: Long) {
        drawnUpTo.update { maxOf(it ?: 0, seq) }
    }

    /** Batches until cancelled or the page stalls. */
    suspend fun run(): Nothing {
        var seq = 0L
        while (true) {
            delay(tick)
            // Paced: the next batch leaves once fewer than `window` are unacknowledged.
            if (drawnUpTo.value != null) drawnUpTo.first { it!! >= seq + 1 - window }
            val events = page.drain()
            if (events.isEmpty()) continue
            withTimeoutOrNull(sendTimeout) { send(GcsBatch(++seq, events)) }
                ?: throw PageStalled("the page read nothing for $sendTimeout")
        }
    }
}

/** A page stopped reading what it is sent. */
internal class PageStalled(message: String) : pod.core.PodException(message)
