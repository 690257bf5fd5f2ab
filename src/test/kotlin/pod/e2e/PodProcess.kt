package pod.e2e

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.cancel
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withTimeout
import java.io.File
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** A running `pod` process (a JVM of its own); its output lines as they come. */
internal class PodProcess(val process: Process, scope: CoroutineScope) {
    val out = MutableStateFlow<List<String>>(emptyList())
    val err = MutableStateFlow<List<String>>(emptyList())

    init {
        for ((stream, lines) in listOf(process.inputStream to out, process.errorStream to err)) {
            scope.launch(Dispatchers.IO) { stream.bufferedReader().forEachLine { line -> lines.value += line } }
        }
    }

    suspend fun awaitOut(timeout: Duration, what: (String) -> Boolean): String = withTimeout(timeout) { out.first { it.any(what) }.first(what) }

    /** Sends signal [name] (INT, TERM) as `kill` does. */
    fun signal(name: String) {
        check(ProcessBuilder("kill", "-$name", process.pid().toString()).start().waitFor() == 0) { "kill -$name failed" }
    }

    suspend fun exitCode(timeout: Duration): Int = withTimeout(timeout) { runInterruptible(Dispatchers.IO) { process.waitFor() } }
}

/**
 * Starts `pod ARGS` as the `./pod` launcher does: `pod.cli.MainKt` on this test's classpath, in a
 * JVM of its own (so that signals reach it), with [environment] added.
 */
internal fun CoroutineScope.startPod(args: List<String>, environment: Map<String, String> = emptyMap()): PodProcess {
    val java = File(System.getProperty("java.home"), "bin/java").path
    // `env --default-signal=INT`: a build started in the background of a non-interactive shell (`mvn … &`)
    // passes SIGINT on as ignored, and a JVM that starts with SIGINT ignored installs no handler for
    // it, so the Ctrl-C these tests send would go unheard; a terminal's `pod` always starts with it.
    val process = ProcessBuilder(
        listOf("env", "--default-signal=INT", java, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "pod.cli.MainKt") + args,
    ).also { it.environment().putAll(environment) }.start()
    process.outputStream.close()
    return PodProcess(process, this)
}

/**
 * Ends [pods] (SIGTERM) and waits for each at most [within]; then cancels [readers], the scope
 * their output readers run in, even if one would not exit, so that it cannot hold a test open.
 */
internal suspend fun stopPods(readers: CoroutineScope, vararg pods: PodProcess, within: Duration = 30.seconds) {
    pods.forEach { it.process.destroy() }
    try {
        pods.forEach { it.exitCode(within) }
    } finally {
        readers.cancel()
    }
}
