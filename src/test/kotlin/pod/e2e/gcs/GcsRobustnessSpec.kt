package pod.e2e.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.assertions.withClue
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import kotlinx.serialization.json.jsonPrimitive
import pod.cli.gcs.PageLimits
import pod.cli.json.Event
import pod.e2e.gcs.PageClient.Companion.awaitValue
import pod.e2e.gcs.PageClient.Companion.kind
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** The page's WebSocket under bad input and bad pages, over real loopback sockets. */
class GcsRobustnessSpec : StringSpec({

    "a malformed frame gets an error reply and the socket stays open; an oversized one is refused with a reason" {
        runBlocking {
            GcsFixture.start(count = 1, limits = PageLimits(maxRequestBytes = 64 * 1024)).use { gcs ->
                val page = PageClient.open(gcs.server.port)
                page.send("{not json")
                page.send("""{"op":"fly_to_the_moon","id":2}""")
                page.send("""{"op":"ping","id":3}""")
                page.reply(3)["ok"]!!.jsonPrimitive.content shouldBe "true"
                val errors = page.events.filter { it.kind == "reply" && it["ok"]!!.jsonPrimitive.content == "false" }
                errors.map { it["id"]!!.jsonPrimitive.content } shouldContainAll listOf("-1", "2")
                errors.forEach { it["error"]!!.jsonPrimitive.content shouldContain "not a request" }
                page.closed shouldBe null

                page.send("""{"op":"ping","id":4,"pad":"${"x".repeat(100 * 1024)}"}""")
                val (code, reason) = page.awaitClosed()
                // The server closes with 1009 as soon as it reads the frame's length, leaving the rest
                // of the frame unread; a socket closed with unread bytes is reset (TCP RST), and a
                // client that had not yet read the close frame then sees an abnormal close (1006)
                // instead. Either way the server ended the page (below); the reason, when it arrives, says why.
                withClue("close $code '$reason'") { ((code == 1009 && "too big" in reason.lowercase()) || code == 1006) shouldBe true }
                awaitValue<Long>("the page's session to end", 10.seconds) { gcs.server.stats.pagesOpen.takeIf { it == 0L } }
            }
        }
    }

    "a request split into fragments is refused once it grows beyond the limit" {
        runBlocking {
            GcsFixture.start(count = 1, limits = PageLimits(maxRequestBytes = 64 * 1024)).use { gcs ->
                val page = PageClient.open(gcs.server.port)
                // The server may close before the last fragments are out: the close is what counts.
                runCatching {
                    page.socket.sendText("""{"op":"ping","id":1,"pad":"""", false).get()
                    repeat(4) { page.socket.sendText("y".repeat(30 * 1024), false).get() }
                    page.socket.sendText("\"}", true).get()
                }
                // 1009, or 1006 when the reset of a close with unread bytes beat the close frame (see above).
                val (code, reason) = page.awaitClosed()
                withClue("close $code '$reason'") { (code == 1009 || code == 1006) shouldBe true }
                awaitValue<Long>("the page's session to end", 10.seconds) { gcs.server.stats.pagesOpen.takeIf { it == 0L } }
            }
        }
    }

    "a page that stops reading is dropped after the send timeout, its backlog bounded, and others go on" {
        runBlocking {
            // A backlog bound well below what 3 s of the loop below adds (≥ 600 events even at 50 ms a
            // round on a loaded machine), so the stuck page drops events before it is dropped itself.
            val limits = PageLimits(maxEvents = 100, sendTimeout = 3.seconds)
            GcsFixture.start(count = 1, limits = limits).use { gcs ->
                val stats = gcs.server.stats
                val stuck = StuckPage(gcs.server.port)
                val line = "x".repeat(8 * 1024)
                // 80 KiB of log every 10 ms (8 MB/s) until the stuck page's buffers are full and it is dropped: at most 60 s.
                for (round in 0 until 6_000) {
                    if (stats.pagesStalled > 0) break
                    repeat(10) { gcs.fleet.logEvent(Event.Warning("$round $line")) }
                    delay(10.milliseconds)
                }
                stats.pagesStalled shouldBe 1L
                stats.eventsDropped shouldBeGreaterThan 0L
                awaitValue<Long>("the stuck page's session to end", 10.seconds) { stats.pagesOpen.takeIf { it == 0L } }
                val fresh = PageClient.open(gcs.server.port)
                fresh.send("""{"op":"ping","id":1}""")
                fresh.reply(1)["ok"]!!.jsonPrimitive.content shouldBe "true"
                stuck.close()
            }
        }
    }

    "many pages at once each get the whole fleet; one more than the limit is turned away with a reason" {
        runBlocking {
            GcsFixture.start(count = 3, limits = PageLimits(maxPages = 20)).use { gcs ->
                val pages = List(20) { PageClient.open(gcs.server.port) }
                for (page in pages) {
                    awaitValue("telemetry of all three vehicles on every page", 30.seconds) {
                        page.events.filter { it.kind == "telemetry" }.map { it["sysid"]!!.jsonPrimitive.content }.toSet().takeIf { it.size == 3 }
                    }
                }
                gcs.server.stats.pagesOpen shouldBe 20L
                val extra = PageClient.open(gcs.server.port)
                val (code, reason) = extra.awaitClosed()
                code shouldBe 1013
                reason shouldContain "too many pages"
                pages.forEach { it.socket.abort() }
                awaitValue<Long>("every session to end", 10.seconds) { gcs.server.stats.pagesOpen.takeIf { it == 0L } }
            }
        }
    }

    "a page closed while its requests run leaves the server serving the next page" {
        runBlocking {
            GcsFixture.start(count = 1).use { gcs ->
                val page = PageClient.open(gcs.server.port)
                repeat(50) { page.send("""{"op":"ping","id":$it}""") }
                page.socket.abort()
                awaitValue<Long>("the closed page's session to end", 10.seconds) { gcs.server.stats.pagesOpen.takeIf { it == 0L } }
                val next = PageClient.open(gcs.server.port)
                next.send("""{"op":"ping","id":1}""")
                next.reply(1)["detail"]!!.jsonPrimitive.content shouldBe "pong"
            }
        }
    }
})
