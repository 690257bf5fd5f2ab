package pod.bench

import java.io.File
import java.io.IOException
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlin.concurrent.thread
import kotlin.time.Duration

/**
 * A peer program (a Python ground station, a simulated fleet in another JVM) running as a
 * subprocess that reports on stdout, one flat JSON object per line with an "event" field. Its
 * stderr goes to a temporary file, appended to [log] under [title] on [close]. Events other than
 * the awaited ones go to [onOther], in order, from [await]'s thread.
 */
class PeerProcess(
    command: List<String>,
    private val title: String,
    private val log: File?,
    private val onOther: (Map<String, String>) -> Unit = {},
) : AutoCloseable {
    private val stderr: File = File.createTempFile("bench-peer-", ".log").apply { deleteOnExit() }

    private val process: Process = ProcessBuilder(command).redirectError(stderr).start()

    private val events = LinkedBlockingQueue<Map<String, String>>()

    init {
        thread(isDaemon = true, name = "peer-stdout") {
            try {
                process.inputStream.bufferedReader().forEachLine { line ->
                    if (line.startsWith("{")) JsonText.parseFlat(line)?.let(events::put)
                }
            } catch (_: IOException) {
                // Killed mid-line.
            }
            events.put(mapOf("event" to EXITED, "code" to runCatching { process.waitFor().toString() }.getOrDefault("?")))
        }
    }

    /** The peer's stdin, for peers that run until it closes. */
    val stdin: java.io.OutputStream get() = process.outputStream

    /**
     * Blocks until the peer prints [event] (returned), exits or prints an error (returned as such,
     * with "event" = [EXITED] or "error"), or [limit] passes (null).
     */
    fun await(event: String, limit: Duration): Map<String, String>? {
        val deadline = System.nanoTime() + limit.inWholeNanoseconds
        while (true) {
            val left = deadline - System.nanoTime()
            if (left <= 0) return null
            val next = events.poll(left, TimeUnit.NANOSECONDS) ?: return null
            when (next["event"]) {
                event, EXITED, "error" -> return next
                else -> onOther(next)
            }
        }
    }

    /** The peer's stderr so far. */
    fun stderrLines(): List<String> = runCatching { stderr.readLines() }.getOrDefault(emptyList())

    /** Waits up to [limit] for the peer to exit by itself; true if it did. */
    fun waitForExit(limit: Duration): Boolean = process.waitFor(limit.inWholeMilliseconds, TimeUnit.MILLISECONDS)

    override fun close() {
        // A peer's own children (mavsdk_server) outlive it unless the tree goes with it.
        val tree = process.descendants().toList()
        process.destroyForcibly()
        tree.forEach { it.destroyForcibly() }
        process.waitFor(5, TimeUnit.SECONDS)
        log?.appendText("== $title\n" + stderr.readText())
        stderr.delete()
    }

    companion object {
        /** The pseudo-event put when the peer's stdout closes. */
        const val EXITED = "exited"
    }
}
