package pod.cli.gcs

import io.ktor.websocket.Frame
import io.ktor.websocket.readText
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.channels.ReceiveChannel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import pod.cli.json.Event
import pod.cli.json.Reply
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration

/**
 * One page's side of the WebSocket, without the socket: [hello] first, then the batches of a
 * [PageBatcher] fed by [parts], while every text frame [incoming] brings is a request answered by
 * [answer] in [work] (the fleet's scope, so a takeoff goes on when the page closes) and replied in a
 * later batch. A frame that is not a request (binary, not JSON, an unknown op) gets an error reply
 * and the page stays open; beyond [PageLimits.maxRunning] requests at once the page is told "busy".
 */
internal class PageConversation(
    private val work: CoroutineScope,
    private val answer: suspend (String) -> Reply,
    private val limits: PageLimits,
    private val tick: Duration = FeedPart.TICK,
    private val stats: GcsStats = GcsStats(),
) {
    /**
     * Talks with the page until [incoming] ends (the page closed) or the page stalls
     * ([PageStalled]); either way the page's feeds stop, and its running requests go on in [work].
     */
    suspend fun run(hello: Event, parts: List<suspend (PageFeed) -> Unit>, incoming: ReceiveChannel<Frame>, send: suspend (Event) -> Unit) = coroutineScope {
        val page = PageFeed(limits.maxEvents, stats::dropped)
        send(hello)
        parts.forEach { part -> launch { part(page) } }
        val batcher = PageBatcher(page, tick, limits.sendTimeout, send = send)
        launch { batcher.run() }
        val running = AtomicInteger()
        try {
            for (frame in incoming) {
                val text = (frame as? Frame.Text)?.readText()
                val drawn = text?.let(::drawnSeq)
                when {
                    text == null -> page.add(Reply(-1, ok = false, error = "a request is a JSON text frame, not ${frame.frameType.name.lowercase()}"))
                    drawn != null -> batcher.drawn(drawn)
                    running.incrementAndGet() > limits.maxRunning -> {
                        running.decrementAndGet()
                        stats.busy()
                        page.add(Reply(GcsRequests.idOf(text), ok = false, error = "busy: ${limits.maxRunning} requests of this page are still running"))
                    }
                    else -> work.launch {
                        try {
                            page.add(answer(text))
                        } finally {
                            running.decrementAndGet()
                        }
                    }
                }
            }
        } finally {
            coroutineContext.cancelChildren()
        }
    }
}

private val DRAWN = Regex("""^\{\s*"drawn"\s*:\s*(\d{1,18})\s*}$""")

/** The batch number of a page's `{"drawn": seq}` (it took in every batch up to seq), null for any other frame. */
internal fun drawnSeq(text: String): Long? = DRAWN.matchEntire(text)?.groupValues?.get(1)?.toLong()
