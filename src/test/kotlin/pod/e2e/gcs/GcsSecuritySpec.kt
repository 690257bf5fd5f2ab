package pod.e2e.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import pod.cli.gcs.GcsServer
import pod.e2e.gcs.PageClient.Companion.get
import pod.e2e.gcs.PageClient.Companion.handshakeStatus
import pod.e2e.gcs.PageClient.Companion.kind
import pod.e2e.startPod
import pod.e2e.stopPods
import java.net.Socket
import kotlin.time.Duration.Companion.seconds

/**
 * Who may use `pod gcs`: bound beyond loopback (0.0.0.0 here, every request still sent to
 * 127.0.0.1) nothing is served without the token, not even the page's scripts; no other origin
 * may open the WebSocket; a loopback server answers loopback host names only.
 */
class GcsSecuritySpec : StringSpec({

    "bound to 0.0.0.0 the page, its scripts and its WebSocket need the token; with it the page works in a browser" {
        runBlocking {
            GcsFixture.start(count = 1, host = "0.0.0.0").use { gcs ->
                val port = gcs.server.port
                val token = gcs.server.access.token!!
                gcs.url shouldBe "http://0.0.0.0:$port/?token=$token"
                for (path in listOf("/", "/js/app.js", "/css/map.css")) {
                    get(port, path).statusCode() shouldBe 401
                    get(port, "$path?token=wrong").statusCode() shouldBe 401
                    get(port, path, mapOf("Authorization" to "Bearer ${token.reversed()}")).statusCode() shouldBe 401
                    get(port, path, mapOf("Authorization" to "Bearer $token")).statusCode() shouldBe 200
                }
                handshakeStatus(port) shouldBe 401
                handshakeStatus(port, "?token=wrong") shouldBe 401
                handshakeStatus(port, "?token=$token") shouldBe 101
                handshakeStatus(port, "?token=$token", mapOf("Origin" to "http://evil.example")) shouldBe 403

                val page = get(port, "/?token=$token")
                page.statusCode() shouldBe 200
                page.headers().firstValue("Set-Cookie").get() shouldContain "HttpOnly"
                page.headers().firstValue("Set-Cookie").get() shouldContain "SameSite=Strict"
                page.headers().firstValue("X-Frame-Options").get() shouldBe "DENY"
                page.headers().firstValue("Content-Security-Policy").get() shouldContain "frame-ancestors 'none'"
                page.headers().firstValue("Referrer-Policy").get() shouldBe "no-referrer"

                val client = PageClient.open(port, "?token=$token")
                PageClient.awaitValue("the hello", 10.seconds) { client.messages.firstOrNull() }.kind shouldBe "gcs_hello"
                client.send("""{"op":"ping","id":7}""")
                client.reply(7)["detail"].toString() shouldBe "\"pong\""
                client.socket.abort()

                withContext(Dispatchers.IO) {
                    GcsBrowser().use { browser ->
                        browser.open("http://127.0.0.1:$port/?token=$token")
                        browser.awaitTrue("the page connected") { browser.find("#connection").text == "connected" }
                        browser.awaitTrue("one fleet row") { browser.findAll("#fleet tbody tr").size == 1 }
                        // The token leaves the address bar; the page reloads on its cookie alone.
                        browser.js("return location.search") shouldBe ""
                        browser.open("http://127.0.0.1:$port/")
                        browser.awaitTrue("the page connected again on its cookie") { browser.find("#connection").text == "connected" }
                        browser.awaitTrue("one fleet row again") { browser.findAll("#fleet tbody tr").size == 1 }
                        browser.screenshot("security-token-page")
                    }
                }
            }
        }
    }

    "a loopback server refuses a request naming another host (DNS rebinding)" {
        runBlocking {
            GcsFixture.start(count = 1).use { gcs ->
                val port = gcs.server.port
                gcs.server.access.token shouldBe null
                rawStatus(port, "evil.example:$port") shouldBe 403
                rawStatus(port, "127.0.0.1.evil.example:$port") shouldBe 403
                rawStatus(port, "localhost:$port") shouldBe 200
                rawStatus(port, "127.0.0.1:$port") shouldBe 200
                handshakeStatus(port, headers = mapOf("Origin" to "http://evil.example")) shouldBe 403
                handshakeStatus(port, headers = mapOf("Origin" to "http://127.0.0.1:$port")) shouldBe 101
            }
        }
    }

    "pod gcs bound to 0.0.0.0 prints the URL with a token once, and serves only with it" {
        runBlocking {
            val processes = CoroutineScope(SupervisorJob() + Dispatchers.IO)
            val pod = processes.startPod(listOf("gcs", "--http", "0.0.0.0:0", "--sim", "1"))
            try {
                val line = pod.awaitOut(90.seconds) { "?token=" in it }
                val url = Regex("""http://0\.0\.0\.0:(\d+)/\?token=([0-9a-f]{32})""").find(line)!!
                val (port, token) = url.destructured
                get(port.toInt(), "/").statusCode() shouldBe 401
                get(port.toInt(), "/?token=$token").statusCode() shouldBe 200
                handshakeStatus(port.toInt(), "?token=$token") shouldBe 101
                (pod.out.value + pod.err.value).filter { token in it } shouldHaveSize 1
            } finally {
                stopPods(processes, pod)
            }
            (pod.out.value + pod.err.value).filter { "token=" in it } shouldHaveSize 1
            pod.out.value.first { "?token=" in it } shouldStartWith "pod gcs: 1 simulated copters; open http://0.0.0.0:"
        }
    }
})

/** The status of `GET /` sent raw with Host: [host] (the JDK's clients will not send a Host of our choosing). */
private fun rawStatus(port: Int, host: String): Int = Socket("127.0.0.1", port).use { s ->
    s.getOutputStream().write("GET / HTTP/1.1\r\nHost: $host\r\nConnection: close\r\n\r\n".toByteArray())
    s.getInputStream().bufferedReader().readLine().split(' ')[1].toInt()
}
