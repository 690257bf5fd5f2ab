package pod.cli.gcs

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeSortedBy
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.ints.shouldBeInRange
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.longs.shouldBeGreaterThanOrEqual
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import pod.cli.json.Event
import pod.cli.json.GcsBatch
import pod.cli.json.Reply
import pod.cli.json.VehicleStatus
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** The page's batching in virtual time: what a page gets however fast (or slowly) things change. */
class PageBatcherTest : StringSpec({
    val tick = 100.milliseconds

    /** A state under key "status:1" whose value is [i]. */
    fun state(i: Int) = VehicleStatus(1, awaiting = "$i", text = null, severity = null)
    fun valueOf(e: Event) = (e as VehicleStatus).awaiting!!.toInt()

    "however fast a state changes, a page gets at most one batch per tick, holding the latest value" {
        runTest {
            val page = PageFeed()
            val batches = ArrayList<Pair<Long, GcsBatch>>()
            val setAt = LongArray(10_000)
            val batcher = launch { PageBatcher(page, tick, 30.seconds) { batches += testScheduler.currentTime to it as GcsBatch }.run() }
            for (i in 0 until 10_000) { // one change a virtual millisecond for 10 s
                page.latest("status:1", state(i))
                setAt[i] = testScheduler.currentTime
                delay(1)
            }
            delay(tick * 2)
            batcher.cancel()
            batches.size shouldBeInRange 99..101
            batches.map { it.second.seq } shouldBe (1L..batches.size).toList()
            batches.zipWithNext { a, b -> b.first - a.first }.forEach { it shouldBeGreaterThanOrEqual tick.inWholeMilliseconds }
            for ((at, batch) in batches) {
                batch.events.size shouldBe 1
                val v = valueOf(batch.events.single())
                // Conflated to the latest: the next value was set only after this batch left.
                if (v + 1 < setAt.size) setAt[v + 1] shouldBeGreaterThanOrEqual at
            }
            valueOf(batches.last().second.events.single()) shouldBe 9_999
        }
    }

    "events arrive in order and none is lost while the page keeps up" {
        runTest {
            val page = PageFeed(maxEvents = 5_000)
            val received = ArrayList<Event>()
            val batcher = launch { PageBatcher(page, tick, 30.seconds) { received += (it as GcsBatch).events }.run() }
            val random = Random(28)
            var next = 0L
            repeat(2_000) { // bursts of up to 40 events, 1..30 ms apart
                repeat(random.nextInt(0, 41)) { page.add(Reply(next++, ok = true)) }
                delay(random.nextLong(1, 31))
            }
            delay(tick * 2)
            batcher.cancel()
            received.map { (it as Reply).id } shouldContainExactly (0L until next).toList()
        }
    }

    "a page that reads slowly gets the latest states and the newest events, told how many it missed" {
        runTest {
            val page = PageFeed(maxEvents = 100)
            val batches = ArrayList<GcsBatch>()
            val batcher = launch {
                PageBatcher(page, tick, 30.seconds) { batches += it as GcsBatch; delay(1.seconds) }.run()
            }
            var next = 0L
            for (i in 0 until 5_000) { // 10 events and one state change a virtual millisecond for 5 s
                repeat(10) { page.add(Reply(next++, ok = true)) }
                page.latest("status:1", state(i))
                delay(1)
            }
            delay(3.seconds)
            batcher.cancel()
            val ids = batches.flatMap { b -> b.events.filterIsInstance<Reply>().map { it.id } }
            val missed = batches.flatMap { b -> b.events.filterIsInstance<Event.Warning>() }
                .sumOf { Regex("""(\d+) events were not sent""").find(it.message)!!.groupValues[1].toLong() }
            batches.size shouldBeLessThanOrEqual 10
            batches.forEach { it.events.filterIsInstance<Reply>().size shouldBeLessThanOrEqual 100 }
            ids.shouldBeSortedBy { it }
            ids.toSet().size shouldBe ids.size
            (ids.size + missed) shouldBe next
            missed.toInt() shouldBeGreaterThan 0
            ids.last() shouldBe next - 1
            valueOf(batches.last().events.filterIsInstance<VehicleStatus>().single()) shouldBe 4_999
        }
    }

    "a page that reads nothing is given up once a batch has waited the send timeout" {
        runTest {
            val page = PageFeed()
            page.add(Reply(1, ok = true))
            shouldThrow<PageStalled> { PageBatcher(page, tick, 5.seconds) { awaitCancellation() }.run() }
            testScheduler.currentTime shouldBe (tick + 5.seconds).inWholeMilliseconds
        }
    }

    "no batch is sent while nothing changed" {
        runTest {
            var sent = 0
            val batcher = launch { PageBatcher(PageFeed(), tick, 30.seconds) { sent++ }.run() }
            delay(10.seconds)
            batcher.cancel()
            sent shouldBe 0
        }
    }

    "a page that says what it drew is paced by it: at most two batches on their way, each with the latest state" {
        runTest {
            val page = PageFeed()
            val sent = ArrayList<GcsBatch>()
            lateinit var batcher: PageBatcher
            batcher = PageBatcher(page, tick, 30.seconds) { sent += it as GcsBatch }
            val running = launch { batcher.run() }
            page.latest("status:1", state(0))
            delay(tick + 1.milliseconds)
            sent.size shouldBe 1
            batcher.drawn(1) // from now on the page paces its batches
            // A slow page: it takes in a batch every 500 ms while the state changes every millisecond.
            val drawing = launch {
                while (true) {
                    delay(500)
                    sent.lastOrNull()?.let { batcher.drawn(it.seq - 1) } // one behind: two in flight at most
                }
            }
            for (i in 1..5_000) {
                page.latest("status:1", state(i))
                delay(1)
                (sent.last().seq - (sent.size - 1).toLong()) shouldBe 1L // numbered without gaps
            }
            drawing.cancel()
            running.cancel()
            // Five seconds at one batch per 500 ms of drawing, not fifty at one per tick.
            sent.size shouldBeInRange 10..13
            sent.drop(1).forEach { it.events.size shouldBe 1 } // one state each: conflated while waiting
        }
    }

    "a page's drawn word is read exactly, and anything else is a request" {
        drawnSeq("""{"drawn":42}""") shouldBe 42L
        drawnSeq("""{ "drawn" : 7 }""") shouldBe 7L
        drawnSeq("""{"drawn":-1}""") shouldBe null
        drawnSeq("""{"op":"ping","id":1}""") shouldBe null
        drawnSeq("""{"drawn":1,"op":"ping"}""") shouldBe null
    }
})
