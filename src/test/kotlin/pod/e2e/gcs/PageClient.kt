package pod.e2e.gcs

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.delay
import kotlinx.coroutines.future.await
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.net.http.WebSocket
import java.net.http.WebSocketHandshakeException
import java.util.concurrent.CompletionStage
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * A page as a non-browser client sees it, through the JDK's java.net.http: plain GETs and the
 * page's WebSocket, whose messages it keeps ([messages]) and whose close code and reason it
 * records. [reading] false: it takes the first message and then reads nothing more, as a stuck page.
 */
internal class PageClient private constructor(val socket: WebSocket, private val listener: Listener) {
    val messages: List<JsonObject> get() = listener.messages
    val closed: Pair<Int, String>? get() = listener.closed

    /** Every event of every batch so far. */
    val events: List<JsonObject> get() = messages.filter { it.kind == "gcs_batch" }.flatMap { b -> b["events"]!!.jsonArray.map { it.jsonObject } }

    fun send(text: String) = socket.sendText(text, true).get()

    /** The reply to request [id], once it came. */
    suspend fun reply(id: Long, timeout: Duration = 10.seconds): JsonObject =
        awaitValue("the reply to request $id", timeout) { events.firstOrNull { it.kind == "reply" && it["id"]!!.jsonPrimitive.content == "$id" } }

    suspend fun awaitClosed(timeout: Duration = 10.seconds): Pair<Int, String> = awaitValue("the socket to close", timeout) { closed }

    class Listener(private val reading: Boolean) : WebSocket.Listener {
        val messages = CopyOnWriteArrayList<JsonObject>()
        @Volatile var closed: Pair<Int, String>? = null
        private val text = StringBuilder()

        override fun onOpen(webSocket: WebSocket) = webSocket.request(1)

        override fun onText(webSocket: WebSocket, data: CharSequence, last: Boolean): CompletionStage<*>? {
            text.append(data)
            if (last) {
                messages += Json.parseToJsonElement(text.toString()).jsonObject
                text.setLength(0)
            }
            if (reading || !last) webSocket.request(1)
            return null
        }

        override fun onClose(webSocket: WebSocket, statusCode: Int, reason: String): CompletionStage<*>? {
            closed = statusCode to reason
            return null
        }

        override fun onError(webSocket: WebSocket, error: Throwable) {
            closed = -1 to (error.message ?: error::class.simpleName!!)
        }
    }

    companion object {
        val http: HttpClient = HttpClient.newHttpClient()

        /** Opens `ws://127.0.0.1:[port]/ws` with [headers] and the [query]; throws [WebSocketHandshakeException] when refused. */
        suspend fun open(port: Int, query: String = "", headers: Map<String, String> = emptyMap(), reading: Boolean = true): PageClient {
            val listener = Listener(reading)
            val builder = http.newWebSocketBuilder()
            headers.forEach { (k, v) -> builder.header(k, v) }
            val socket = builder.buildAsync(URI("ws://127.0.0.1:$port/ws$query"), listener).await()
            return PageClient(socket, listener)
        }

        /** The HTTP status of opening the WebSocket: 101 when it opened (then closed again), else the refusal's. */
        suspend fun handshakeStatus(port: Int, query: String = "", headers: Map<String, String> = emptyMap()): Int = try {
            open(port, query, headers).socket.abort()
            101
        } catch (e: Exception) {
            val cause = generateSequence<Throwable>(e) { it.cause }.filterIsInstance<WebSocketHandshakeException>().firstOrNull() ?: throw e
            cause.response.statusCode()
        }

        /** GET http://127.0.0.1:[port][path] with [headers]. */
        suspend fun get(port: Int, path: String, headers: Map<String, String> = emptyMap()): HttpResponse<String> {
            val request = HttpRequest.newBuilder(URI("http://127.0.0.1:$port$path")).also { r -> headers.forEach { (k, v) -> r.header(k, v) } }.build()
            return http.sendAsync(request, HttpResponse.BodyHandlers.ofString()).await()
        }

        val JsonObject.kind: String? get() = this["event"]?.jsonPrimitive?.content

        /** Polls [what] every 50 ms until it is non-null, failing with [description] after [timeout]. */
        suspend fun <T : Any> awaitValue(description: String, timeout: Duration, what: () -> T?): T = try {
            withTimeout(timeout) {
                var value = what()
                while (value == null) {
                    delay(50.milliseconds)
                    value = withContext(Dispatchers.IO) { what() }
                }
                value
            }
        } catch (e: kotlinx.coroutines.TimeoutCancellationException) {
            throw AssertionError("timed out after $timeout waiting for $description", e)
        }
    }
}
