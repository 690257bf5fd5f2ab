package pod.cli.gcs

import io.ktor.http.HttpHeaders
import io.ktor.http.HttpMethod
import io.ktor.server.request.ApplicationRequest
import io.ktor.server.request.header
import io.ktor.server.request.httpMethod
import java.security.MessageDigest
import java.security.SecureRandom

/**
 * Who may use the page. Bound to a loopback address (the default) it serves this machine only,
 * and only under a loopback host name, so that a web page elsewhere cannot reach it through a DNS
 * name pointed at 127.0.0.1. Bound elsewhere it needs [token] on every request: as `?token=` (the
 * URL `pod gcs` prints, after which the page keeps it in a cookie), an `Authorization: Bearer`
 * header or that cookie. A WebSocket or any request that changes something must also come from the
 * page's own origin ([HttpHeaders.Origin] equal to the host it asked for), whatever the binding.
 */
public class GcsAccess(
    /** Needed on every request; null: none (loopback only). */
    public val token: String?,
    /** Whether the server is bound to a loopback address. */
    public val loopback: Boolean,
) {
    init {
        require(loopback || token != null) { "a server bound beyond loopback needs a token" }
    }

    /** Why [request] is refused, null when it is allowed. [webSocket]: it asks to open the page's WebSocket. */
    public fun refusal(request: ApplicationRequest, webSocket: Boolean): String? {
        val host = request.header(HttpHeaders.Host) ?: return "no Host header"
        if (loopback && !isLoopbackHost(host)) return "this server answers to loopback host names only, not '$host'"
        val origin = request.header(HttpHeaders.Origin)
        if ((webSocket || request.httpMethod != HttpMethod.Get) && origin != null && origin != "http://$host") {
            return "cross-origin request from $origin refused"
        }
        val expected = token ?: return null
        val given = request.queryParameters["token"]
            ?: request.header(HttpHeaders.Authorization)?.removePrefix("Bearer ")?.trim()
            ?: request.cookies[COOKIE]
            ?: return "a token is needed: open the URL pod gcs printed"
        return if (sameToken(given, expected)) null else "wrong token"
    }

    public companion object {
        /** The cookie the page keeps the token in. */
        public const val COOKIE: String = "pod_gcs_token"

        /** A new random token: 128 bits, hex. */
        public fun newToken(): String {
            val bytes = ByteArray(16).also { SecureRandom().nextBytes(it) }
            return bytes.joinToString("") { "%02x".format(it) }
        }

        /** Whether [address] (an IP literal or a host name) is this machine only. */
        public fun isLoopbackAddress(address: String): Boolean {
            val a = address.removePrefix("[").removeSuffix("]")
            return a == "localhost" || a == "::1" || a.startsWith("127.")
        }

        private fun isLoopbackHost(hostHeader: String): Boolean {
            val host = if (hostHeader.startsWith("[")) hostHeader.substringBefore("]") + "]" else hostHeader.substringBeforeLast(":")
            return isLoopbackAddress(host)
        }

        private fun sameToken(a: String, b: String): Boolean = MessageDigest.isEqual(a.encodeToByteArray(), b.encodeToByteArray())
    }
}
