package pod.bench.command

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.runInterruptible
import pod.bench.PeerProcess
import java.io.File
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * The sim fleet server (SimFleetServer.kt) in a JVM of its own (same java, same class path, its own 512 MiB heap),
 * started once per harness run; [start] and [stop] one fleet per case and ground station.
 */
class FleetProcess private constructor(private val peer: PeerProcess) : AutoCloseable {
    /** Starts [case]'s vehicles sending to loopback [port]; null when they are running, else what went wrong. */
    suspend fun start(case: CommandCase, seed: Long, port: Int): String? {
        val reply = command("start ${case.vehicles} ${case.lossPercent} $seed $port", "started")
        return if (reply?.get("event") == "started") null else "fleet did not start: ${reply ?: "no answer within $ANSWER"}"
    }

    /** Stops the running fleet; returns the server's counters (relay drops), empty when it did not answer. */
    suspend fun stop(): Map<String, String> = command("stop", "stopped")?.takeIf { it["event"] == "stopped" } ?: emptyMap()

    /** CPU seconds the fleet's JVM has used so far, or null when it did not answer. */
    suspend fun cpuSeconds(): Double? = command("cpu", "cpu")?.get("seconds")?.toDoubleOrNull()

    private suspend fun command(line: String, answer: String): Map<String, String>? = runInterruptible(Dispatchers.IO) {
        peer.stdin.write("$line\n".toByteArray())
        peer.stdin.flush()
        peer.await(answer, ANSWER)
    }

    override fun close() {
        runCatching { peer.stdin.close() }
        peer.waitForExit(10.seconds)
        peer.close()
    }

    companion object {
        private val ANSWER = 60.seconds

        /**
         * Starts the server and waits for its warm-up; returns it with the "ready" event's fields.
         * [log] collects its stderr.
         */
        suspend fun open(log: File?): Pair<FleetProcess, Map<String, String>> {
            val java = File(System.getProperty("java.home"), "bin/java").path
            val peer = PeerProcess(
                listOf(
                    java, "-Xms512m", "-Xmx512m",
                    "-cp", System.getProperty("java.class.path"), "pod.bench.command.SimFleetServerKt",
                ),
                "sim fleet server", log,
            )
            val ready = runInterruptible(Dispatchers.IO) { peer.await("ready", 3.minutes) }
            if (ready?.get("event") != "ready") {
                peer.close()
                error("sim fleet server did not get ready: ${ready ?: "nothing within 3 minutes"}")
            }
            return FleetProcess(peer) to ready
        }
    }
}
