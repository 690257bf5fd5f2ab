package pod.cli.gcs

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.string.shouldMatch
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.string
import io.kotest.property.checkAll
import io.ktor.http.HttpStatusCode

class GcsAccessTest : StringSpec({
    val token = "0123456789abcdef0123456789abcdef"
    val local = GcsAccess(token = null, loopback = true)
    val remote = GcsAccess(token = token, loopback = false)

    fun GcsAccess.status(host: String? = "127.0.0.1:8080", origin: String? = null, changes: Boolean = false, query: String? = null, authorization: String? = null, cookie: String? = null) =
        refusal(host, origin, changes, query, authorization, cookie)?.status

    "a loopback server answers loopback host names and refuses every other name (DNS rebinding)" {
        for (host in listOf("localhost", "localhost:8080", "LOCALHOST:1", "127.0.0.1:8080", "127.9.8.7", "[::1]:8080", "[::1]", "[0:0:0:0:0:0:0:1]:80")) {
            withClue(host) { local.status(host = host).shouldBeNull() }
        }
        val foreign = listOf(
            "evil.example:8080", "127.0.0.1.evil.example:8080", "127.attacker.example", "localhost.evil.example",
            "0.0.0.0:8080", "10.0.0.1:8080", "[::]:8080", "[fe80::1]:80", "127.0.0.256:80", "2130706433:8080",
        )
        for (host in foreign) withClue(host) { local.status(host = host) shouldBe HttpStatusCode.Forbidden }
    }

    "every IPv4 literal in 127/8 is loopback and none outside it is" {
        checkAll(Arb.int(0..255), Arb.int(0..255), Arb.int(0..255), Arb.int(0..255)) { a, b, c, d ->
            GcsAccess.isLoopbackAddress("$a.$b.$c.$d") shouldBe (a == 127)
            GcsAccess.isLoopbackHost("$a.$b.$c.$d:8080") shouldBe (a == 127)
            GcsAccess.isLoopbackAddress("$a.$b.$c.$d.example") shouldBe false
        }
    }

    "no name is taken for loopback unless it is localhost or a literal, whatever it holds" {
        checkAll(Arb.string(0..30)) { s ->
            if (s.lowercase().removeSuffix(".") != "localhost" && s.any { it.isLetter() && it.lowercaseChar() !in 'a'..'f' }) {
                GcsAccess.isLoopbackAddress(s) shouldBe false
            }
        }
    }

    "beyond loopback every request needs the token, from the query, a Bearer header or the cookie" {
        remote.status() shouldBe HttpStatusCode.Unauthorized
        remote.status(query = "wrong") shouldBe HttpStatusCode.Unauthorized
        remote.status(query = token.dropLast(1)) shouldBe HttpStatusCode.Unauthorized
        remote.status(query = token + "0") shouldBe HttpStatusCode.Unauthorized
        remote.status(authorization = "Basic $token") shouldBe HttpStatusCode.Unauthorized
        remote.status(query = token).shouldBeNull()
        remote.status(authorization = "Bearer $token").shouldBeNull()
        remote.status(authorization = "bearer  $token").shouldBeNull()
        remote.status(cookie = token).shouldBeNull()
        // The query names the token the page was opened with; a stale cookie does not override it, nor it a wrong one.
        remote.status(query = "wrong", cookie = token) shouldBe HttpStatusCode.Unauthorized
        remote.status(host = "192.168.1.5:8080", query = token).shouldBeNull()
    }

    "a WebSocket or a change from another origin is refused, even with the token" {
        remote.status(origin = "http://evil.example", changes = true, query = token) shouldBe HttpStatusCode.Forbidden
        remote.status(origin = "null", changes = true, query = token) shouldBe HttpStatusCode.Forbidden
        remote.status(origin = "https://127.0.0.1:8080", changes = true, query = token) shouldBe HttpStatusCode.Forbidden
        remote.status(origin = "http://127.0.0.1:8080", changes = true, query = token).shouldBeNull()
        local.status(origin = "http://evil.example", changes = true) shouldBe HttpStatusCode.Forbidden
        local.status(origin = "http://LOCALHOST:8080", host = "localhost:8080", changes = true).shouldBeNull()
        // A page elsewhere may link an image here (a GET); it cannot read it, and it changes nothing.
        local.status(origin = "http://evil.example").shouldBeNull()
        // Tools (curl, java.net.http) send no Origin: on loopback they are this machine's own.
        local.status(changes = true).shouldBeNull()
    }

    "a request without a Host header is refused" {
        local.status(host = null) shouldBe HttpStatusCode.BadRequest
        remote.status(host = "", query = token) shouldBe HttpStatusCode.BadRequest
    }

    "tokens are 128 random bits in hex and each server names its cookie differently" {
        val tokens = List(50) { GcsAccess.newToken() }
        tokens.forEach { it shouldMatch Regex("[0-9a-f]{32}") }
        tokens.toSet().size shouldBe 50
        GcsAccess(token, false).cookieName shouldNotBe GcsAccess(token, false).cookieName
    }

    "a server beyond loopback cannot be made without a token" {
        shouldThrow<IllegalArgumentException> { GcsAccess(token = null, loopback = false) }
    }
})
