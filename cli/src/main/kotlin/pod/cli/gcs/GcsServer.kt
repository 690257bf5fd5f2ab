package pod.cli.gcs

import io.ktor.http.Cookie
import io.ktor.http.HttpStatusCode
import io.ktor.server.application.ApplicationCallPipeline
import io.ktor.server.application.call
import io.ktor.server.application.install
import io.ktor.server.cio.CIO
import io.ktor.server.engine.embeddedServer
import io.ktor.server.http.content.staticResources
import io.ktor.server.response.respondText
import io.ktor.server.routing.routing
import io.ktor.server.websocket.WebSockets
import io.ktor.server.websocket.webSocket
import io.ktor.server.websocket.pingPeriod
import io.ktor.server.websocket.timeout
import io.ktor.websocket.ChannelOverflow
import io.ktor.http.HttpHeaders
import io.ktor.server.request.header
import io.ktor.server.request.path
import kotlin.time.Duration.Companion.seconds

/**
 * The ground station's HTTP server: the page (HTML, CSS and JavaScript from this jar, under
 * [WEB_ROOT]), its WebSocket at `/ws` ([PageSession]) and whatever routes the page's features add.
 * Every request passes [access] first.
 */
public class GcsServer private constructor(
    private val server: io.ktor.server.engine.EmbeddedServer<*, *>,
    /** The port it listens on (the one asked for, or the free one it got for 0). */
    public val port: Int,
    /** The URL to open: with the token when one is needed. */
    public val url: String,
    public val access: GcsAccess,
    public val stats: GcsStats,
) : AutoCloseable {

    /** Stops serving: open pages lose their WebSocket (the fleet and what runs on it stay). */
    override fun close() {
        server.stop(gracePeriodMillis = 100, timeoutMillis = 2_000)
    }

    public companion object {
        /** Where the page's files are on the classpath. */
        public const val WEB_ROOT: String = "pod/gcs/web"

        /** Frames a page's WebSocket holds for a page that is not reading before a send waits. */
        private const val OUTGOING_FRAMES = 8

        /**
         * Serves [fleet] on [host]:[port] (port 0: any free one). A [host] beyond loopback gets a
         * new random token unless [token] is given; on loopback [token] is optional. [limits] bound
         * what each page may cost.
         * @throws GcsRequestException when the address cannot be bound (in use, not this machine's).
         */
        public suspend fun start(fleet: GcsFleet, host: String = "127.0.0.1", port: Int = 8080, token: String? = null, limits: PageLimits = PageLimits()): GcsServer {
            val loopback = GcsAccess.isLoopbackAddress(host)
            val access = GcsAccess(token ?: if (loopback) null else GcsAccess.newToken(), loopback)
            val stats = GcsStats()
            val session = PageSession(fleet, stats, limits)
            val server = embeddedServer(CIO, host = host, port = port) {
                install(WebSockets) {
                    pingPeriod = 15.seconds
                    timeout = 30.seconds
                    maxFrameSize = limits.maxRequestBytes
                    // Ktor's outgoing channel is unbounded by default: a page that stops reading would
                    // queue every batch in the server's memory. Bounded, a send waits for the page
                    // (PageBatcher conflates meanwhile, and gives up after PageLimits.sendTimeout).
                    channels { outgoing = bounded(OUTGOING_FRAMES, ChannelOverflow.SUSPEND) }
                }
                intercept(ApplicationCallPipeline.Plugins) {
                    GcsHeaders.secure(call.response)
                    val ws = call.request.header(HttpHeaders.Upgrade).equals("websocket", ignoreCase = true)
                    val refused = access.refusal(call.request, ws)
                    if (refused != null) {
                        call.respondText(refused.reason, status = refused.status)
                        finish()
                        return@intercept
                    }
                    // The page's own files are asked for without the token: it rides in a cookie.
                    val given = call.request.queryParameters["token"]
                    if (access.token != null && given != null && call.request.path() == "/") {
                        call.response.cookies.append(Cookie(access.cookieName, given, path = "/", httpOnly = true, extensions = mapOf("SameSite" to "Strict")))
                    }
                }
                routing {
                    webSocket("/ws") { session.serve(this) }
                    planRoutes(fleet)
                    staticResources("/", WEB_ROOT)
                }
            }
            try {
                server.start(wait = false)
            } catch (e: java.io.IOException) {
                throw GcsRequestException("cannot serve on $host:$port: ${e.message}")
            }
            val bound = server.engine.resolvedConnectors().first().port
            val shown = if (host.contains(':')) "[$host]" else host
            val url = "http://$shown:$bound/" + (access.token?.let { "?token=$it" } ?: "")
            return GcsServer(server, bound, url, access, stats)
        }
    }
}
