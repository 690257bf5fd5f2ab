package pod.cli.gcs

import io.ktor.server.websocket.DefaultWebSocketServerSession
import io.ktor.websocket.Frame
import io.ktor.websocket.readText
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.cli.json.GcsBatch
import pod.cli.json.GcsHello
import pod.cli.json.Reply
import java.util.concurrent.atomic.AtomicInteger

/**
 * One open page: its WebSocket gets a [GcsHello], then at most one [GcsBatch] per [FeedPart.TICK]
 * with what every [FeedPart] gathered; each text frame the page sends is a [GcsRequest], answered
 * by a [Reply] in a later batch. Requests run in the fleet's scope: a takeoff asked for goes on
 * when the page is closed, as it would from a terminal.
 */
internal class PageSession(private val fleet: GcsFleet, private val stats: GcsStats) {

    suspend fun serve(ws: DefaultWebSocketServerSession) = coroutineScope {
        val page = PageFeed()
        send(ws, GcsHello(fleet.source, fleet.tiles, fleet.timeScale, (1000 / FeedPart.TICK.inWholeMilliseconds).toInt()))
        FeedPart.ALL.forEach { part -> launch { part.feed(fleet, page) } }
        launch {
            var seq = 0L
            while (true) {
                delay(FeedPart.TICK)
                val events = page.drain()
                if (events.isNotEmpty()) send(ws, GcsBatch(++seq, events))
            }
        }
        val running = AtomicInteger()
        try {
            for (frame in ws.incoming) {
                if (frame !is Frame.Text) continue
                val text = frame.readText()
                if (running.incrementAndGet() > MAX_RUNNING) {
                    running.decrementAndGet()
                    page.add(Reply(GcsRequests.idOf(text), ok = false, error = "busy: $MAX_RUNNING requests of this page are still running"))
                    continue
                }
                fleet.scope.launch {
                    try {
                        page.add(GcsRequests.answer(fleet, text))
                    } finally {
                        running.decrementAndGet()
                    }
                }
            }
        } finally {
            coroutineContext.cancelChildren()
        }
    }

    private suspend fun send(ws: DefaultWebSocketServerSession, event: Event) {
        val bytes = EventJson.encode(event).encodeToByteArray()
        ws.send(Frame.Text(true, bytes))
        stats.sent(bytes.size)
    }

    private companion object {
        /** Requests of one page running at once; more are refused ("busy") rather than queued without bound. */
        const val MAX_RUNNING = 64
    }
}
