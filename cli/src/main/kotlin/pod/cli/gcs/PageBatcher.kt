package pod.cli.gcs

import kotlinx.coroutines.delay
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
 */
internal class PageBatcher(
    private val page: PageFeed,
    private val tick: Duration,
    private val sendTimeout: Duration,
    private val send: suspend (Event) -> Unit,
) {
    /** Batches until cancelled or the page stalls. */
    suspend fun run(): Nothing {
        var seq = 0L
        while (true) {
            delay(tick)
            val events = page.drain()
            if (events.isEmpty()) continue
            withTimeoutOrNull(sendTimeout) { send(GcsBatch(++seq, events)) }
                ?: throw PageStalled("the page read nothing for $sendTimeout")
        }
    }
}

/** A page stopped reading what it is sent. */
internal class PageStalled(message: String) : Exception(message)
