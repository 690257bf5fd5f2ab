package pod.mavlink.telemetry

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.string
import io.kotest.property.checkAll
import io.kotest.property.arbitrary.Codepoint
import io.kotest.property.arbitrary.az
import pod.core.vehicle.Autopilot
import pod.core.vehicle.Severity
import pod.core.vehicle.StatusText

private const val SECOND = 1_000_000_000L

/** [text] cut as ArduPilot's GCS::send_textv cuts it: (chunk_seq, chunk) pairs, the last one shorter than 50. */
private fun chunks(text: String): List<Pair<Int, String>> =
    (0..text.length / 50).map { i -> i to text.substring(minOf(i * 50, text.length), minOf((i + 1) * 50, text.length)) }

/** [text] cut as PX4's MavlinkStreamStatustext::send cuts it: chunks of 50, the last one holding the end (full when the text fills it). */
private fun px4Chunks(text: String): List<Pair<Int, String>> =
    (0 until maxOf(1, (text.length + 49) / 50)).map { i -> i to text.substring(i * 50, minOf((i + 1) * 50, text.length)) }

class StatusTextJoinerTest : StringSpec({
    val line = "Mode change to AUTO RTL failed: No landing sequence found"

    "a text that fits is one line; chunks with one id are joined into the line they were cut from" {
        val joiner = StatusTextJoiner()
        joiner.feed(Severity.INFO, "Armed\u0000\u0000", 0, 0, 0) shouldBe listOf(StatusText(Severity.INFO, "Armed"))
        val (first, second) = chunks(line)
        joiner.feed(Severity.WARNING, first.second, 7, 0, 0).shouldBeEmpty()
        joiner.feed(Severity.WARNING, second.second + "\u0000", 7, 1, 0) shouldBe listOf(StatusText(Severity.WARNING, line))
        joiner.flush(10 * SECOND).shouldBeEmpty()
    }

    "any text, its chunks in any order, comes out whole and once" {
        checkAll(300, Arb.string(0..200, Codepoint.az()), Arb.int(1..65535), Arb.int()) { text, id, seed ->
            val joiner = StatusTextJoiner()
            val out = ArrayList<StatusText>()
            for ((seq, chunk) in chunks(text).shuffled(kotlin.random.Random(seed))) {
                out += joiner.feed(Severity.NOTICE, chunk, id, seq, 0)
            }
            out shouldBe listOf(StatusText(Severity.NOTICE, text))
            joiner.flush(10 * SECOND).shouldBeEmpty()
        }
    }

    "a line whose last chunk is lost is delivered with what came, once its time is up" {
        val joiner = StatusTextJoiner(timeoutNanos = SECOND)
        joiner.feed(Severity.WARNING, chunks(line)[0].second, 3, 0, 0).shouldBeEmpty()
        joiner.flush(SECOND / 2).shouldBeEmpty()
        joiner.flush(SECOND) shouldBe listOf(StatusText(Severity.WARNING, line.take(50)))
        joiner.flush(2 * SECOND).shouldBeEmpty()
    }

    "lines interleaved with different ids are joined apart; too many open lines deliver the oldest" {
        val joiner = StatusTextJoiner(maxPending = 2)
        val a = "a".repeat(50) + "A"
        val b = "b".repeat(50) + "B"
        joiner.feed(Severity.INFO, a.take(50), 1, 0, 0).shouldBeEmpty()
        joiner.feed(Severity.INFO, b.take(50), 2, 0, 0).shouldBeEmpty()
        joiner.feed(Severity.INFO, "B", 2, 1, 0) shouldBe listOf(StatusText(Severity.INFO, b))
        joiner.feed(Severity.INFO, "c".repeat(50), 3, 0, 0).shouldBeEmpty()
        joiner.feed(Severity.INFO, "d".repeat(50), 4, 0, 0) shouldBe listOf(StatusText(Severity.INFO, "a".repeat(50)))
    }

    "PX4's first text is chunked with id 0: its chunks come out as one line (they came apart: 'Resolve system health failures firs', 't')" {
        val joiner = StatusTextJoiner()
        val denied = "Arming denied: Resolve system health failures first"
        val (first, second) = px4Chunks(denied)
        joiner.feed(Severity.CRITICAL, first.second, 0, 0, 0, Autopilot.PX4).shouldBeEmpty()
        joiner.feed(Severity.CRITICAL, second.second, 0, 1, 0, Autopilot.PX4) shouldBe listOf(StatusText(Severity.CRITICAL, denied))
        joiner.flush(10 * SECOND).shouldBeEmpty()
    }

    "PX4's texts, numbered from 0 and ending on a full chunk when they fill it, come out whole, in order and once" {
        checkAll(200, Arb.list(Arb.string(0..160, Codepoint.az()), 1..6), Arb.int(0..65535)) { texts, firstId ->
            val joiner = StatusTextJoiner()
            val out = ArrayList<StatusText>()
            texts.forEachIndexed { n, text ->
                val id = (firstId + n) and 0xFFFF
                for ((seq, chunk) in px4Chunks(text)) out += joiner.feed(Severity.INFO, chunk, id, seq, 0, Autopilot.PX4)
            }
            out += joiner.flush(10 * SECOND)
            out shouldBe texts.map { StatusText(Severity.INFO, it) }
        }
    }

    "from ArduPilot, id 0 is a whole text even when it fills the field" {
        val joiner = StatusTextJoiner()
        joiner.feed(Severity.INFO, "x".repeat(50), 0, 0, 0, Autopilot.ARDUPILOT) shouldBe listOf(StatusText(Severity.INFO, "x".repeat(50)))
    }
})
