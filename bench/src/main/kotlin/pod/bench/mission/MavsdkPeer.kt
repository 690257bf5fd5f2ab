package pod.bench.mission

import pod.bench.PeerProcess
import java.io.File
import kotlin.time.Duration

/** Where the MAVSDK ground station comes from: the venv's Python and bench/mavsdk_mission.py. */
data class MavsdkSetup(val python: File, val script: File, val log: File?)

/**
 * bench/mavsdk_mission.py running as a subprocess, listening on loopback [port]: its stdout read
 * as one flat JSON object per line. [close] kills it and its mavsdk_server child.
 */
class MavsdkPeer(setup: MavsdkSetup, port: Int, items: File, limits: Limits, title: String) : AutoCloseable {
    /** The "item" events printed so far, in order. */
    val items = mutableListOf<Map<String, String>>()

    private val process = PeerProcess(
        listOf(
            setup.python.path, setup.script.path, "--port", port.toString(), "--items", items.path, "--download",
            "--discover-seconds", limits.discovery.inWholeSeconds.toString(),
            "--transfer-seconds", limits.transfer.inWholeSeconds.toString(),
        ),
        title, setup.log,
        onOther = { if (it["event"] == "item") this.items += it },
    )

    /**
     * Blocks until the peer prints [event] (returned), exits or prints an error (returned as such,
     * with "event" = [EXITED] or "error"), or [limit] passes (null). Items met on the way are kept.
     */
    fun await(event: String, limit: Duration): Map<String, String>? = process.await(event, limit)

    override fun close() = process.close()

    /** MAVSDK's last warning or error on stderr (e.g. "Timeout: retries exceeded (…)"), without colour codes; read it before [close]. */
    fun lastWarning(): String? =
        process.stderrLines().map { it.replace(ANSI, "") }.lastOrNull { "|Warn" in it || "|Error" in it }?.substringAfter("] ")?.trim()

    companion object {
        /** The pseudo-event put when the peer's stdout closes. */
        const val EXITED = PeerProcess.EXITED

        private val ANSI = Regex("\u001B\\[[0-9;]*m")
    }
}
