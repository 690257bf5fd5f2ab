package pod.cli.gcs

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.ktor.websocket.Frame
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.runTest
import pod.cli.json.Event
import pod.cli.json.GcsBatch
import pod.cli.json.GcsHello
import pod.cli.json.Reply
import kotlin.time.Duration.Companion.seconds

/** A page's conversation without a socket, in virtual time: requests, bad frames, closing mid-request. */
class PageConversationTest : StringSpec({

    "a frame that is not a request gets an error reply and the page stays open" {
        runTest {
            val page = TestPage(this, backgroundScope)
            page.incoming.send(Frame.Text("not json"))
            page.incoming.send(Frame.Binary(true, byteArrayOf(1, 2, 3)))
            page.incoming.send(Frame.Text("""{"op":"no_such_op","id":3}"""))
            page.incoming.send(Frame.Text("""{"op":"ping"}"""))
            page.incoming.send(Frame.Text("""{"op":"ping","id":5}"""))
            delay(1.seconds)
            page.sent.first() shouldBe HELLO
            val r: List<Reply> = page.replies()
            // Requests run concurrently, so replies come in any order: each frame has its own.
            r.map { it.id }.sorted() shouldBe listOf(-1L, -1L, -1L, 3L, 5L)
            r.map { it.error.orEmpty().substringBefore(":") }.sorted() shouldBe listOf("", "a request is a JSON text frame, not binary", "not a request", "not a request", "not a request")
            r.single { it.id == 5L } shouldBe Reply(5, ok = true, detail = "pong")
            page.job.isActive shouldBe true
            page.incoming.close()
            delay(1.seconds)
            page.job.isCompleted shouldBe true
        }
    }

    "a page closed while its requests run lets them finish in the fleet's scope" {
        runTest {
            val work = CoroutineScope(backgroundScope.coroutineContext + SupervisorJob())
            val gate = CompletableDeferred<Unit>()
            var done = 0
            val page = TestPage(this, work) { _ -> gate.await(); done++; "done" }
            repeat(3) { page.incoming.send(Frame.Text("""{"op":"ping","id":$it}""")) }
            delay(1.seconds)
            page.incoming.close()
            delay(1.seconds)
            page.job.isCompleted shouldBe true
            val workJob: Job = work.coroutineContext[Job]!!
            workJob.children.count() shouldBe 3
            gate.complete(Unit)
            delay(1.seconds)
            done shouldBe 3
            workJob.isActive shouldBe true
        }
    }

    "beyond its running limit a page's request is answered busy at once, and taken again once one ends" {
        runTest {
            val gate = CompletableDeferred<Unit>()
            val page = TestPage(this, backgroundScope, PageLimits(maxRunning = 2)) { _ -> gate.await(); "done" }
            repeat(3) { page.incoming.send(Frame.Text("""{"op":"ping","id":$it}""")) }
            delay(1.seconds)
            val busy: Reply = page.replies().single()
            busy.id shouldBe 2L
            busy.error.orEmpty().startsWith("busy") shouldBe true
            gate.complete(Unit)
            delay(1.seconds)
            page.incoming.send(Frame.Text("""{"op":"ping","id":9}"""))
            delay(1.seconds)
            page.replies().filter { it.ok }.map { it.id }.toSet() shouldBe setOf(0L, 1L, 9L)
            page.incoming.close()
        }
    }

    "a page that stops reading ends its conversation with PageStalled once a batch waited the send timeout" {
        runTest {
            val incoming = Channel<Frame>(Channel.UNLIMITED)
            incoming.send(Frame.Text("""{"op":"ping","id":1}"""))
            val answer: suspend (String) -> Reply = { text -> GcsRequests.answer(text, ::pong) }
            val conversation = PageConversation(backgroundScope, answer, PageLimits(sendTimeout = 2.seconds))
            shouldThrow<PageStalled> { conversation.run(HELLO, emptyList(), incoming, ::stuck) }
            testScheduler.currentTime shouldBe (FeedPart.TICK + 2.seconds).inWholeMilliseconds
        }
    }
})

private val HELLO: GcsHello = GcsHello("test", null, 1.0, 10)

private suspend fun pong(request: GcsRequest): String? = "pong"

/** A page that takes the hello and then reads nothing. */
private suspend fun stuck(event: Event) {
    if (event is GcsBatch) awaitCancellation()
}

/** A page talking to a conversation whose requests run [carryOut] in [work]. */
private class TestPage(test: TestScope, work: CoroutineScope, limits: PageLimits = PageLimits(), carryOut: suspend (GcsRequest) -> String? = ::pong) {
    val incoming: Channel<Frame> = Channel(Channel.UNLIMITED)
    val sent: MutableList<Event> = ArrayList()
    val job: Job

    init {
        val answer: suspend (String) -> Reply = { text -> GcsRequests.answer(text, carryOut) }
        val conversation = PageConversation(work, answer, limits)
        job = test.launch { conversation.run(HELLO, emptyList(), incoming) { e -> sent.add(e) } }
    }

    fun replies(): List<Reply> = sent.filterIsInstance<GcsBatch>().flatMap { it.events }.filterIsInstance<Reply>()
}
