package pod.mavlink.tlog

import pod.core.time.Timebase
import java.io.BufferedOutputStream
import java.io.IOException
import java.io.OutputStream
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.StandardOpenOption
import kotlin.time.Duration.Companion.seconds

/**
 * Appends [TlogRecord]s to a stream in the tlog format (see [TlogRecord]).
 *
 * Thread-safe: a ground station writes received frames from its receive thread and sent frames
 * from its senders. Writes are buffered; the buffer goes to the stream at least once a second
 * of [timebase]'s clock while records come (so a crash loses at most about a second), on [flush] and on [close].
 * Writing after [close], or a failing stream, throws [TlogWriteFailed].
 */
public class TlogWriter(
    out: OutputStream,
    /** What "a second" is measured on (the station's timebase); a test passes its own. */
    private val timebase: Timebase = Timebase.System,
) : AutoCloseable {
    private val out = BufferedOutputStream(out, 64 * 1024)
    private val lock = Any()
    private val header = ByteArray(TlogFrames.TIMESTAMP)
    private var lastFlush = timebase.clock.markNow()
    private var closed = false

    /** Records written so far. */
    @Volatile public var records: Long = 0
        private set

    /**
     * Appends one record: [timestampMicros] (microseconds since the Unix epoch) and [frame], which
     * must be exactly one complete MAVLink frame (IllegalArgumentException otherwise: a tlog with a
     * wrong length in it cannot be read past that record).
     */
    public fun write(timestampMicros: Long, frame: ByteArray) {
        requireOneFrame(frame)
        synchronized(lock) {
            if (closed) throw TlogWriteFailed("tlog writer is closed")
            for (i in 0 until TlogFrames.TIMESTAMP) header[i] = (timestampMicros ushr (56 - 8 * i)).toByte()
            try {
                out.write(header)
                out.write(frame)
                records++
                if (lastFlush.elapsedNow() >= FLUSH_INTERVAL) {
                    out.flush()
                    lastFlush = timebase.clock.markNow()
                }
            } catch (e: IOException) {
                throw TlogWriteFailed("cannot write to the tlog: ${e.message}", e)
            }
        }
    }

    /** Appends [record]. */
    public fun write(record: TlogRecord): Unit = write(record.timestampMicros, record.frame)

    /** Pushes buffered records to the stream. */
    public fun flush() {
        synchronized(lock) {
            if (closed) return
            try {
                out.flush()
                lastFlush = timebase.clock.markNow()
            } catch (e: IOException) {
                throw TlogWriteFailed("cannot write to the tlog: ${e.message}", e)
            }
        }
    }

    /** Flushes and closes the stream; later writes throw, a second close does nothing. */
    override fun close() {
        synchronized(lock) {
            if (closed) return
            closed = true
            try {
                out.close()
            } catch (e: IOException) {
                throw TlogWriteFailed("cannot close the tlog: ${e.message}", e)
            }
        }
    }

    private fun requireOneFrame(frame: ByteArray) {
        require(frame.size >= TlogFrames.LENGTH_PREFIX) { "frame must be a MAVLink frame, was ${frame.size} bytes" }
        when (val length = TlogFrames.lengthOf(frame, 0)) {
            is TlogFrames.Result.NotAFrame -> throw IllegalArgumentException("frame must be a MAVLink frame: ${length.reason}")
            is TlogFrames.Result.Length -> require(length.bytes == frame.size) {
                "frame must be exactly one MAVLink frame: its header says ${length.bytes} bytes, was ${frame.size}"
            }
        }
    }

    /** Creates tlog files. */
    public companion object {
        private val FLUSH_INTERVAL = 1.seconds

        /** A writer to a new file at [path] (replacing one that is there), or appending to it when [append]. */
        public fun create(path: Path, append: Boolean = false): TlogWriter {
            val options = if (append) {
                arrayOf(StandardOpenOption.CREATE, StandardOpenOption.APPEND, StandardOpenOption.WRITE)
            } else {
                arrayOf(StandardOpenOption.CREATE, StandardOpenOption.TRUNCATE_EXISTING, StandardOpenOption.WRITE)
            }
            return try {
                TlogWriter(Files.newOutputStream(path, *options))
            } catch (e: IOException) {
                throw TlogWriteFailed("cannot open $path for writing: ${e.message}", e)
            }
        }

        /** Microseconds since the Unix epoch now, by the system's wall clock: what a tlog's timestamps count. */
        public fun wallClockMicros(): Long {
            val now = java.time.Instant.now()
            return now.epochSecond * 1_000_000 + now.nano / 1_000
        }
    }
}
