package pod.bench.radio

import pod.bench.PeerProcess
import java.io.File
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlin.concurrent.thread
import kotlin.time.Duration.Companion.seconds

/** The Python ground stations of the radio benchmark, each run as a bounded subprocess. */
internal object PythonPeers {
    /** bench/pymavlink_radio_upload.py's own time, MISSION_COUNT sent to MISSION_ACK received. */
    fun pymavlink(python: File, port: Int, wpl: File): Double {
        val script = File("bench/pymavlink_radio_upload.py")
        PeerProcess(listOf(python.path, script.path, "--connect", "udpin:127.0.0.1:$port", "--wpl", wpl.path, "--timeout", "120"), "pymavlink", null).use { peer ->
            val ready = peer.await("ready", 40.seconds) ?: error("pymavlink: no vehicle within 40 s")
            check(ready["event"] == "ready") { "pymavlink: $ready" }
            val done = peer.await("uploaded", 130.seconds) ?: error("pymavlink: no answer within 130 s")
            check(done["event"] == "uploaded") { "pymavlink: $done" }
            return done.getValue("seconds").toDouble()
        }
    }

    /**
     * MAVProxy's own time for `wp load` (its "Loaded N waypoints in X s": MISSION_COUNT sent to the
     * last item sent, one item short of the final MISSION_ACK), typed on its stdin once it has
     * detected the vehicle, as a person would.
     */
    fun mavproxy(python: File, mavproxy: File, port: Int, wpl: File, items: Int): Double {
        val dir = kotlin.io.path.createTempDirectory("bench-mavproxy-").toFile()
        val process = ProcessBuilder(python.absolutePath, mavproxy.absolutePath, "--master=udpin:127.0.0.1:$port", "--state-basedir=${dir.path}")
            .directory(dir).redirectErrorStream(true).start()
        val lines = LinkedBlockingQueue<String>()
        thread(isDaemon = true, name = "mavproxy-stdout") { runCatching { process.inputStream.bufferedReader().forEachLine { lines.put(it) } } }
        try {
            await(lines, 40) { "Detected vehicle" in it || "online system" in it } ?: error("MAVProxy: no vehicle within 40 s")
            process.outputStream.write("wp load ${wpl.absolutePath}\n".toByteArray())
            process.outputStream.flush()
            val loaded = Regex("Loaded $items waypoints in ([0-9.]+)s")
            val line = await(lines, 130) { loaded.containsMatchIn(it) } ?: error("MAVProxy: no upload within 130 s")
            return loaded.find(line)!!.groupValues[1].toDouble()
        } finally {
            process.destroy()
            if (!process.waitFor(10, TimeUnit.SECONDS)) process.destroyForcibly()
            dir.deleteRecursively()
        }
    }

    private fun await(lines: LinkedBlockingQueue<String>, seconds: Long, match: (String) -> Boolean): String? {
        val deadline = System.nanoTime() + seconds * 1_000_000_000
        while (true) {
            val left = deadline - System.nanoTime()
            if (left <= 0) return null
            val line = lines.poll(left, TimeUnit.NANOSECONDS) ?: return null
            if (match(line)) return line
        }
    }
}
