package pod.bench.mission

import java.io.File
import java.io.IOException
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlin.concurrent.thread
import kotlin.time.Duration

/** Where the MAVSDK ground station comes from: the venv's Python and bench/mavsdk_mission.py. */
data class MavsdkSetup(val python: File, val script: File, val log: File?)

/**
 * bench/mavsdk_mission.py running as a subprocess, listening on loopback [port]: its stdout read
 * as one flat JSON object per line. [close] kills it and its mavsdk_server child.
 */
class MavsdkPeer(private val setup: MavsdkSetup, port: Int, items: File, limits: Limits, private val title: String) : AutoCloseable {
    // Its own stderr file, so that MAVSDK's warnings can be told apart per run (and then go to the shared log).
    private val stderr: File = File.createTempFile("mission-bench-mavsdk-", ".log").apply { deleteOnExit() }

    private val process: Process = ProcessBuilder(
        setup.python.path, setup.script.path, "--port", port.toString(), "--items", items.path, "--download",
        "--discover-seconds", limits.discovery.inWholeSeconds.toString(),
        "--transfer-seconds", limits.transfer.inWholeSeconds.toString(),
    ).redirectError(stderr).start()

    private val events = LinkedBlockingQueue<Map<String, String>>()

    /** The "item" events printed so far, in order. */
    val items = mutableListOf<Map<String, String>>()

    init {
        thread(isDaemon = true, name = "mavsdk-stdout") {
            try {
                process.inputStream.bufferedReader().forEachLine { line ->
                    if (line.startsWith("{")) events.put(parseFlatJson(line))
                }
            } catch (_: IOException) {
                // Killed mid-line.
            }
            events.put(mapOf("event" to EXITED, "code" to runCatching { process.waitFor().toString() }.getOrDefault("?")))
        }
    }

    /**
     * Blocks until the peer prints [event] (returned), exits or prints an error (returned as such,
     * with "event" = [EXITED] or "error"), or [limit] passes (null). Items met on the way are kept.
     */
    fun await(event: String, limit: Duration): Map<String, String>? {
        val deadline = System.nanoTime() + limit.inWholeNanoseconds
        while (true) {
            val left = deadline - System.nanoTime()
            if (left <= 0) return null
            val next = events.poll(left, TimeUnit.NANOSECONDS) ?: return null
            when (next["event"]) {
                "item" -> items += next
                event, EXITED, "error" -> return next
            }
        }
    }

    override fun close() {
        // os._exit in the watchdog leaves mavsdk_server behind unless the tree goes with it.
        val tree = process.descendants().toList()
        process.destroyForcibly()
        tree.forEach { it.destroyForcibly() }
        process.waitFor(5, TimeUnit.SECONDS)
        setup.log?.appendText("== $title\n" + stderr.readText())
        stderr.delete()
    }

    /** MAVSDK's last warning or error on stderr (e.g. "Timeout: retries exceeded (…)"), without colour codes; read it before [close]. */
    fun lastWarning(): String? = runCatching {
        stderr.readLines().map { it.replace(ANSI, "") }.lastOrNull { "|Warn" in it || "|Error" in it }?.substringAfter("] ")?.trim()
    }.getOrNull()

    companion object {
        /** The pseudo-event put when the peer's stdout closes. */
        const val EXITED = "exited"

        private val ANSI = Regex("\u001B\\[[0-9;]*m")

        private val FIELD = Regex("""\"(\w+)\":\s*("(?:[^"\\]|\\.)*"|[^,}]+)""")

        private fun parseFlatJson(line: String): Map<String, String> =
            FIELD.findAll(line).associate { m -> m.groupValues[1] to m.groupValues[2].trim().removeSurrounding("\"") }
    }
}
