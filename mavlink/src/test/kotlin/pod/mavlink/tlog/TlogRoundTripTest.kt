package pod.mavlink.tlog

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.property.Arb
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import kotlinx.coroutines.Dispatchers
import pod.core.time.Timebase
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.TestFrames
import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream
import java.io.IOException
import java.io.OutputStream
import java.nio.file.Files
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.TestTimeSource

private fun tlogOf(records: List<TlogRecord>): ByteArray {
    val out = ByteArrayOutputStream()
    TlogWriter(out).use { writer -> records.forEach(writer::write) }
    return out.toByteArray()
}

private fun read(bytes: ByteArray): List<TlogRecord> = TlogReader(ByteArrayInputStream(bytes)).use { it.readAll() }

private fun randomRecords(random: Random, count: Int): List<TlogRecord> =
    List(count) { TlogRecord(random.nextLong(), TestFrames.random(random)) }

class TlogRoundTripTest : StringSpec({

    "random frames (MAVLink 1 and 2, signed, unknown ids) and timestamps come back exactly, in order" {
        checkAll(300, Arb.list(Arb.long(), 0..30), Arb.long()) { timestamps, seed ->
            val random = Random(seed)
            val records = timestamps.map { TlogRecord(it, TestFrames.random(random)) }
            val bytes = tlogOf(records)
            read(bytes) shouldBe records
            // The layout is the one pymavlink reads: 8 bytes big-endian, then the frame, nothing else.
            bytes.size shouldBe records.sumOf { 8 + it.frame.size }
        }
    }

    "the timestamp is 8 bytes big-endian before the frame" {
        val frame = TestFrames.random(Random(1))
        val bytes = tlogOf(listOf(TlogRecord(0x0102030405060708, frame)))
        bytes.copyOfRange(0, 8).toList() shouldBe listOf<Byte>(1, 2, 3, 4, 5, 6, 7, 8)
        bytes.copyOfRange(8, bytes.size).contentEquals(frame) shouldBe true
    }

    "signed MAVLink 2 frames keep their 13 signature bytes" {
        val random = Random(7)
        val records = List(20) { TlogRecord(it.toLong(), TestFrames.signed(random)) }
        val back = read(tlogOf(records))
        back shouldBe records
        back.forEach { FrameDecoder().decodeAllSigned(it.frame) shouldBe 13 }
    }

    "a tlog cut anywhere inside a record throws TlogTruncated after the complete records; cut between records it reads them all" {
        checkAll(300, Arb.long(), Arb.int(1..8)) { seed, count ->
            val random = Random(seed)
            val records = randomRecords(random, count)
            val bytes = tlogOf(records)
            val boundaries = records.runningFold(0) { at, r -> at + 8 + r.frame.size }
            val cut = random.nextInt(bytes.size)
            val complete = boundaries.indexOfLast { it <= cut }
            val reader = TlogReader(ByteArrayInputStream(bytes.copyOf(cut)))
            repeat(complete) { reader.next() shouldBe records[it] }
            if (cut == boundaries[complete]) {
                reader.next() shouldBe null
            } else {
                shouldThrow<TlogTruncated> { reader.next() }.offset shouldBe boundaries[complete].toLong()
            }
        }
    }

    "bytes that are not a frame where one should start throw TlogCorrupt naming the record's offset" {
        val records = randomRecords(Random(3), 3)
        val bytes = tlogOf(records)
        val second = 8 + records[0].frame.size
        bytes[second + 8] = 0x55
        val reader = TlogReader(ByteArrayInputStream(bytes))
        reader.next() shouldBe records[0]
        shouldThrow<TlogCorrupt> { reader.next() }.offset shouldBe second.toLong()
    }

    "a known message with a damaged payload is reported, not returned as a wrong frame" {
        val frame = pod.mavlink.copterHeartbeat(1, 0)
        val bytes = tlogOf(listOf(TlogRecord(5, frame)))
        bytes[8 + 12] = (bytes[8 + 12] + 1).toByte() // a payload byte of the heartbeat (MAVLink 2 header: 10 bytes)
        shouldThrow<TlogCorrupt> { read(bytes) }.reason shouldBe "bad checksum for message id 0"
    }

    "unknown MAVLink 2 incompatibility flags are reported" {
        val bytes = tlogOf(listOf(TlogRecord(5, TestFrames.signed(Random(2)))))
        bytes[8 + 2] = 0x03
        shouldThrow<TlogCorrupt> { read(bytes) }
    }

    "random bytes end in records or a typed error, never a hang or an untyped exception" {
        checkAll(500, Arb.long(), Arb.int(0..600)) { seed, size ->
            val garbage = TestFrames.garbage(Random(seed), size)
            try {
                val records = read(garbage)
                // Whatever it accepted re-encodes to exactly the input: nothing was skipped or invented.
                tlogOf(records).contentEquals(garbage) shouldBe true
            } catch (e: TlogException) {
                e.shouldBeInstanceOf<TlogException>()
            }
        }
    }

    "the writer refuses anything but exactly one frame" {
        val frame = TestFrames.random(Random(4))
        TlogWriter(ByteArrayOutputStream()).use { writer ->
            shouldThrow<IllegalArgumentException> { writer.write(1, frame + frame) }
            shouldThrow<IllegalArgumentException> { writer.write(1, frame.copyOf(frame.size - 1)) }
            shouldThrow<IllegalArgumentException> { writer.write(1, byteArrayOf(0x12, 0, 0, 0, 0, 0, 0, 0)) }
            writer.records shouldBe 0
        }
    }

    "buffered records reach the stream once a second of the writer's clock has passed since the last flush" {
        val out = ByteArrayOutputStream()
        val clock = TestTimeSource()
        val writer = TlogWriter(out, Timebase(clock, Dispatchers.Unconfined))
        val frame = TestFrames.random(Random(6))
        writer.write(1, frame)
        clock += 999.milliseconds
        writer.write(2, frame)
        out.size() shouldBe 0
        clock += 1.milliseconds
        writer.write(3, frame)
        out.size() shouldBe 3 * (8 + frame.size)
        writer.write(4, frame)
        out.size() shouldBe 3 * (8 + frame.size) // the second starts again from that flush
        writer.close()
        out.size() shouldBe 4 * (8 + frame.size)
    }

    "writes after close and a failing stream throw TlogWriteFailed" {
        val frame = TestFrames.random(Random(5))
        val writer = TlogWriter(ByteArrayOutputStream())
        writer.close()
        shouldThrow<TlogWriteFailed> { writer.write(1, frame) }
        val broken = TlogWriter(object : OutputStream() {
            override fun write(b: Int) = throw IOException("disk full")
            override fun write(b: ByteArray, off: Int, len: Int) = throw IOException("disk full")
        })
        shouldThrow<TlogWriteFailed> {
            repeat(10_000) { broken.write(1, frame) } // the buffer fills and goes to the stream
            broken.flush()
        }
    }

    "writers on several threads interleave whole records" {
        val out = ByteArrayOutputStream()
        val perThread = 500
        TlogWriter(out).use { writer ->
            val threads = (0 until 4).map { t ->
                Thread {
                    val random = Random(t)
                    repeat(perThread) { writer.write(t * 1_000_000L + it, TestFrames.random(random)) }
                }.apply { start() }
            }
            threads.forEach { it.join(30_000) }
        }
        val back = read(out.toByteArray())
        back.size shouldBe 4 * perThread
        // Each thread's records arrive in its own order, each frame whole.
        back.groupBy { it.timestampMicros / 1_000_000 }.forEach { (t, records) ->
            val random = Random(t.toInt())
            records.map { it.timestampMicros % 1_000_000 } shouldBe (0L until perThread).toList()
            records.forEach { it.frame.contentEquals(TestFrames.random(random)) shouldBe true }
        }
    }

    "a file written with create is read back by open" {
        val path = Files.createTempFile("pod", ".tlog")
        try {
            val records = randomRecords(Random(9), 10)
            TlogWriter.create(path).use { w -> records.forEach(w::write) }
            TlogReader.open(path).use { it.readAll() } shouldBe records
            TlogWriter.create(path, append = true).use { w -> records.forEach(w::write) }
            TlogReader.open(path).use { it.readAll() } shouldBe records + records
        } finally {
            Files.deleteIfExists(path)
        }
    }
})

/** How many signature bytes the single frame in [bytes] carries, as the decoder sees it. */
private fun FrameDecoder.decodeAllSigned(bytes: ByteArray): Int {
    var size = -1
    feed(bytes) { size = it.signature?.size ?: 0 }
    return size
}
