package pod.cli.gcs

import io.ktor.server.websocket.DefaultWebSocketServerSession
import io.ktor.websocket.CloseReason
import io.ktor.websocket.Frame
import io.ktor.websocket.close
import kotlinx.coroutines.cancel
import kotlinx.coroutines.withTimeoutOrNull
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.cli.json.GcsHello
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.seconds

/**
 * One open page on its WebSocket: a [GcsHello], then the batches and replies of a
 * [PageConversation] over the fleet's [FeedPart]s and requests. Beyond [PageLimits.maxPages] pages
 * a new one is closed with a reason at once; a page that stops reading is closed once a batch has
 * waited [PageLimits.sendTimeout] for it (it reconnects and starts afresh when it reads again).
 */
internal class PageSession(private val fleet: GcsFleet, private val stats: GcsStats, private val limits: PageLimits) {
    private val open = AtomicInteger()

    suspend fun serve(ws: DefaultWebSocketServerSession) {
        if (open.incrementAndGet() > limits.maxPages) {
            open.decrementAndGet()
            ws.close(CloseReason(CloseReason.Codes.TRY_AGAIN_LATER, "too many pages open: at most ${limits.maxPages}"))
            return
        }
        stats.pageOpened()
        try {
            val hello = GcsHello(fleet.source, fleet.tiles, fleet.timeScale, (1000 / FeedPart.TICK.inWholeMilliseconds).toInt())
            val parts = FeedPart.ALL.map { part -> suspend { page: PageFeed -> part.feed(fleet, page) } }
            PageConversation(fleet.scope, { GcsRequests.answer(fleet, it) }, limits, stats = stats)
                .run(hello, parts, ws.incoming) { send(ws, it) }
        } catch (e: PageStalled) {
            stats.stalled()
            // The close frame queues behind the batches the page is not reading: try briefly, then drop the connection.
            withTimeoutOrNull(1.seconds) { ws.close(CloseReason(CloseReason.Codes.TRY_AGAIN_LATER, e.message ?: "stalled")) }
            ws.cancel()
        } finally {
            open.decrementAndGet()
            stats.pageClosed()
        }
    }

    private suspend fun send(ws: DefaultWebSocketServerSession, event: Event) {
        val bytes = EventJson.encode(event).encodeToByteArray()
        ws.send(Frame.Text(true, bytes))
        stats.sent(event, bytes.size)
    }
}
