package pod.mavlink.tlog

import pod.mavlink.codec.Crc
import pod.mavlink.codec.MessageCodec
import pod.mavlink.codec.FrameLayout
import java.io.BufferedInputStream
import java.io.IOException
import java.io.InputStream
import java.nio.file.Files
import java.nio.file.Path

/**
 * Reads [TlogRecord]s from a stream in the tlog format (see [TlogRecord]), one at a time.
 *
 * Each frame's length comes from its header (MAVLink 1: 0xFE; MAVLink 2: 0xFD, plus 13 signature
 * bytes when incompatibility flag 0x01 is set). A record cut short at the end of the stream throws
 * [TlogTruncated]; bytes that do not start a frame, unknown MAVLink 2 flags, or a frame of a message
 * the [codec] knows whose checksum is wrong throw [TlogCorrupt]. The reader never guesses past
 * either: a tlog has no markers to resynchronise on. Not thread-safe.
 */
public class TlogReader(input: InputStream, private val codec: MessageCodec = MessageCodec.Default) : AutoCloseable {
    private val input = BufferedInputStream(input, 64 * 1024)
    private var offset = 0L

    /** The next record, or null at the end of the stream (exactly after the last complete record). */
    public fun next(): TlogRecord? {
        val start = offset
        val head = ByteArray(TlogFrames.TIMESTAMP + TlogFrames.LENGTH_PREFIX)
        val got = readFully(head, 0, head.size)
        if (got == 0) return null
        if (got < head.size) {
            // A frame is at least a MAVLink 1 header and checksum: anything shorter is cut off.
            throw TlogTruncated(start, TlogFrames.TIMESTAMP + FrameLayout.HEADER_V1 + FrameLayout.CHECKSUM, got)
        }
        var timestamp = 0L
        for (i in 0 until TlogFrames.TIMESTAMP) timestamp = (timestamp shl 8) or (head[i].toLong() and 0xFF)
        val length = when (val r = TlogFrames.lengthOf(head, TlogFrames.TIMESTAMP)) {
            is TlogFrames.Result.NotAFrame -> throw TlogCorrupt(start, r.reason)
            is TlogFrames.Result.Length -> r.bytes
        }
        val frame = ByteArray(length)
        head.copyInto(frame, 0, TlogFrames.TIMESTAMP)
        val rest = readFully(frame, TlogFrames.LENGTH_PREFIX, length - TlogFrames.LENGTH_PREFIX)
        if (rest < length - TlogFrames.LENGTH_PREFIX) {
            throw TlogTruncated(start, TlogFrames.TIMESTAMP + length, head.size + rest)
        }
        checkCrc(frame, start)
        return TlogRecord(timestamp, frame)
    }

    /** Every remaining record, in order; throws as [next] does. */
    public fun readAll(): List<TlogRecord> = generateSequence { next() }.toList()

    override fun close() {
        input.close()
    }

    private fun checkCrc(frame: ByteArray, start: Long) {
        val v2 = (frame[0].toInt() and 0xFF) == FrameLayout.MAGIC_V2
        val header = if (v2) FrameLayout.HEADER_V2 else FrameLayout.HEADER_V1
        val payload = frame[1].toInt() and 0xFF
        val messageId = if (v2) {
            (frame[7].toInt() and 0xFF) or ((frame[8].toInt() and 0xFF) shl 8) or ((frame[9].toInt() and 0xFF) shl 16)
        } else {
            frame[5].toInt() and 0xFF
        }
        val crcExtra = codec.crcExtra(messageId)
        if (crcExtra < 0) return // a message we do not know: its checksum cannot be checked
        val at = header + payload
        val expected = Crc.frameChecksum(frame, 1, header - 1 + payload, crcExtra)
        val actual = (frame[at].toInt() and 0xFF) or ((frame[at + 1].toInt() and 0xFF) shl 8)
        if (expected != actual) throw TlogCorrupt(start, "bad checksum for message id $messageId")
    }

    /** Reads up to [count] bytes into [into] at [at]; fewer only at the end of the stream. */
    private fun readFully(into: ByteArray, at: Int, count: Int): Int {
        var total = 0
        while (total < count) {
            val n = try {
                input.read(into, at + total, count - total)
            } catch (e: IOException) {
                throw TlogException("cannot read the tlog at byte ${offset + total}: ${e.message}", e)
            }
            if (n < 0) break
            total += n
        }
        offset += total
        return total
    }

    /** Opens tlog files. */
    public companion object {
        /** Opens the tlog at [path]. */
        public fun open(path: Path, codec: MessageCodec = MessageCodec.Default): TlogReader = try {
            TlogReader(Files.newInputStream(path), codec)
        } catch (e: IOException) {
            throw TlogException("cannot open $path: ${e.message}", e)
        }
    }
}
