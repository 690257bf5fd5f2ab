package pod.mavlink.fuzz

import pod.mavlink.codec.MessageCodec
import pod.mavlink.tlog.TlogCorrupt
import pod.mavlink.tlog.TlogReader
import pod.mavlink.tlog.TrackRecorder
import pod.mavlink.tlog.FrameDirection
import pod.mavlink.tlog.TlogTruncated
import java.io.ByteArrayInputStream
import kotlin.random.Random

/**
 * Reading tlogs: each input is a small tlog (1–12 records of corpus frames, 8-byte big-endian
 * timestamps) with one of its frames mutated, or the whole file cut, flipped, shortened or grown.
 * [TlogReader] may refuse it only with its typed errors, [TlogTruncated] and [TlogCorrupt], at the
 * byte offset where the bad record starts: the records before it and the record sizes account for
 * every byte up to there (for every byte of the file when it reads to the end). Each record read
 * goes to a [TrackRecorder], as [pod.mavlink.tlog.TlogTracks.read] hands it on: that must not throw
 * at all, whatever a frame that passed its checksum says.
 */
public class TlogReading(corpus: FuzzCorpus, private val codec: MessageCodec = MessageCodec.Default) : FuzzTarget {
    override val name: String = "tlog"
    private val frames = corpus.frames
    private val mutator = Mutator(frames, codec)

    override fun runOne(random: Random, tally: FuzzTally) {
        val records = List(1 + random.nextInt(MAX_RECORDS)) { frames[random.nextInt(frames.size)] }
        val mutated = random.nextInt(records.size)
        var mutation = Mutation.NONE
        var file = ByteArray(0)
        records.forEachIndexed { i, frame ->
            file += timestamp(random)
            file += if (i == mutated && random.nextInt(4) != 0) mutator.next(random).also { mutation = it.mutation }.bytes else frame
        }
        if (random.nextInt(4) == 0) {
            mutation = WHOLE_FILE[random.nextInt(WHOLE_FILE.size)]
            file = mutator.apply(mutation, file, random)
        }
        tally.input(mutation, file)

        // One pass, as TlogTracks.read makes it: each record read goes to a TrackRecorder, which
        // decodes and checks what it keeps and must never throw.
        val tracks = TrackRecorder(stepMetres = 0.0, codec = codec)
        var consumed = 0L
        TlogReader(ByteArrayInputStream(file), codec).use { reader ->
            try {
                while (true) {
                    val record = reader.next() ?: break
                    consumed += TIMESTAMP + record.frame.size
                    tally.frames++
                    tracks.onFrame(record.timestampMicros, FrameDirection.RECEIVED, record.frame)
                }
                property(consumed == file.size.toLong()) { "read $consumed of ${file.size} bytes and stopped without an error" }
            } catch (e: TlogTruncated) {
                property(e.offset == consumed) { "truncation reported at ${e.offset}, the bad record starts at $consumed" }
                tally.refused++
            } catch (e: TlogCorrupt) {
                property(e.offset == consumed) { "corruption reported at ${e.offset}, the bad record starts at $consumed" }
                tally.refused++
            }
        }
        tracks.tracks()
    }

    private fun timestamp(random: Random): ByteArray {
        val micros = if (random.nextInt(16) == 0) random.nextLong() else 1_764_000_000_000_000L + random.nextLong(1_000_000_000L)
        return ByteArray(8) { (micros ushr (56 - 8 * it)).toByte() }
    }

    private companion object {
        const val MAX_RECORDS = 12
        const val TIMESTAMP = 8
        val WHOLE_FILE = arrayOf(Mutation.BIT_FLIP, Mutation.BYTE_SET, Mutation.INSERT, Mutation.DELETE, Mutation.TRUNCATE)
    }
}
