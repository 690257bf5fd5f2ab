package pod.cli.gcs

import io.ktor.http.HttpHeaders
import io.ktor.http.HttpMethod
import io.ktor.http.HttpStatusCode
import io.ktor.server.request.ApplicationRequest
import io.ktor.server.request.header
import io.ktor.server.request.httpMethod
import java.net.InetAddress
import java.security.MessageDigest
import java.security.SecureRandom

/**
 * Who may use the page. Bound to a loopback address (the default) it serves this machine only,
 * and only under a loopback host name (`localhost`, `127.x.y.z`, `[::1]`), so that a web page
 * elsewhere cannot reach it through a DNS name it points at 127.0.0.1 (DNS rebinding). Bound
 * elsewhere it needs [token] on every request: as `?token=` (the URL `pod gcs` prints, after which
 * the page keeps it in the cookie [cookieName]), an `Authorization: Bearer` header or that cookie;
 * nothing logs it (the one line `pod gcs` prints holds it).
 * A WebSocket, or any request that is not a GET, must also come from the page's own origin
 * ([HttpHeaders.Origin] equal to the host it asked for) when it names one, whatever the binding.
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

    /**
     * The cookie the page keeps the token in once it was opened with `?token=`: a name of this
     * server's own, since a browser sends a host's cookies to every port of it (two `pod gcs` on
     * one machine would otherwise overwrite each other's).
     */
    public val cookieName: String = "pod_gcs_" + newToken().take(8)

    /** Why a request is refused: [status] 401 (no or a wrong token) or 403 (the wrong host or origin). */
    public data class Refusal(val status: HttpStatusCode, val reason: String)

    /** Why [request] is refused, null when it is allowed. [webSocket]: it asks to open the page's WebSocket. */
    public fun refusal(request: ApplicationRequest, webSocket: Boolean): Refusal? = refusal(
        host = request.header(HttpHeaders.Host),
        origin = request.header(HttpHeaders.Origin),
        changes = webSocket || request.httpMethod != HttpMethod.Get,
        queryToken = request.queryParameters["token"],
        authorization = request.header(HttpHeaders.Authorization),
        cookie = request.cookies[cookieName],
    )

    /**
     * Why a request with these headers is refused, null when it is allowed. [changes]: it opens the
     * WebSocket or is not a GET, so it must not come from another origin.
     */
    public fun refusal(host: String?, origin: String?, changes: Boolean, queryToken: String?, authorization: String?, cookie: String?): Refusal? {
        if (host.isNullOrBlank()) return Refusal(HttpStatusCode.BadRequest, "no Host header")
        if (loopback && !isLoopbackHost(host)) {
            return Refusal(HttpStatusCode.Forbidden, "this server answers to loopback host names only (localhost, 127.0.0.1, [::1])")
        }
        if (changes && origin != null && !origin.equals("http://$host", ignoreCase = true)) {
            return Refusal(HttpStatusCode.Forbidden, "cross-origin request refused")
        }
        val expected = token ?: return null
        val given = queryToken ?: bearer(authorization) ?: cookie
            ?: return Refusal(HttpStatusCode.Unauthorized, "a token is needed: open the URL pod gcs printed")
        return if (sameToken(given, expected)) null else Refusal(HttpStatusCode.Unauthorized, "wrong token")
    }

    public companion object {
        /** A new random token: 128 bits from [SecureRandom], hex. */
        public fun newToken(): String {
            val bytes = ByteArray(16).also { SecureRandom().nextBytes(it) }
            return bytes.joinToString("") { "%02x".format(it) }
        }

        /**
         * Whether [address] (`--http`'s host, or a Host header's without the port) names this
         * machine only: `localhost`, an IPv4 literal in 127.0.0.0/8 or the IPv6 loopback, never a
         * DNS name (`127.0.0.1.example.com` is anybody's). No name is looked up.
         */
        public fun isLoopbackAddress(address: String): Boolean {
            val bracketed = address.length >= 2 && address.startsWith("[") && address.endsWith("]")
            val a = (if (bracketed) address.substring(1, address.length - 1) else address).lowercase()
            // An IPv6 literal (hex digits and colons, maybe an embedded IPv4), parsed in brackets
            // so that the JDK refuses a malformed one rather than looking it up.
            if (':' in a) return IPV6_CHARS.matches(a) && runCatching { InetAddress.getByName("[$a]").isLoopbackAddress }.getOrDefault(false)
            if (bracketed) return false
            val name = a.removeSuffix(".")
            if (name == "localhost") return true
            return IPV4.matches(name) && name.startsWith("127.") && name.split('.').all { it.toInt() <= 255 }
        }

        /** Whether a Host header ([hostHeader]: `name`, `name:port`, `[v6]` or `[v6]:port`) names a loopback host. */
        public fun isLoopbackHost(hostHeader: String): Boolean {
            val host = when {
                hostHeader.startsWith("[") -> hostHeader.substringBefore("]") + "]"
                hostHeader.count { it == ':' } == 1 -> hostHeader.substringBefore(":")
                else -> hostHeader
            }
            return isLoopbackAddress(host)
        }

        private val IPV4 = Regex("""\d{1,3}\.\d{1,3}\.\d{1,3}\.\d{1,3}""")
        private val IPV6_CHARS = Regex("""[0-9a-f:.]+""")

        private fun bearer(authorization: String?): String? {
            val parts = authorization?.trim()?.split(' ', limit = 2) ?: return null
            return if (parts.size == 2 && parts[0].equals("Bearer", ignoreCase = true)) parts[1].trim() else null
        }

        /** Compares in time independent of where they differ: digests of equal length, compared whole. */
        private fun sameToken(a: String, b: String): Boolean {
            val sha = { s: String -> MessageDigest.getInstance("SHA-256").digest(s.encodeToByteArray()) }
            return MessageDigest.isEqual(sha(a), sha(b))
        }
    }
}
