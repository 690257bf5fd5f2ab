package pod.e2e

import java.io.File
import java.io.IOException
import java.nio.file.Files
import java.util.concurrent.CompletableFuture
import java.util.concurrent.TimeUnit
import java.util.concurrent.TimeoutException
import kotlin.concurrent.thread

/**
 * A pseudo-terminal pair made by `socat`, standing in for a serial cable between two radios: what
 * is written to the device [a] comes out of [b], and back. [a] and [b] are symlinks in a fresh
 * directory to the `/dev/pts/N` nodes socat made; open them as `serial://$a:57600`.
 *
 * [unplug] ends socat, as pulling a USB radio does: both nodes hang up and vanish. [plugIn] starts
 * a new socat on the same two paths (new nodes behind them), as plugging it back in. [close] ends
 * socat and removes the directory; use it in a `finally` (or `use`).
 */
internal class Socat private constructor(private val dir: File) : AutoCloseable {
    /** One end's path. */
    val a: String = File(dir, "a").path

    /** The other end's path. */
    val b: String = File(dir, "b").path

    @Volatile private var process: Process? = null

    /** Whether socat is running (the pair exists). */
    val pluggedIn: Boolean get() = process?.isAlive == true

    /**
     * Starts socat and returns once it says both ends exist ("starting data transfer loop", which it
     * logs after making and linking both terminals), at most [within] ms.
     */
    fun plugIn(within: Long = 10_000) {
        check(!pluggedIn) { "socat is already running for $dir" }
        val started = ProcessBuilder(
            executable, "-d", "-d",
            "pty,raw,echo=0,link=$a",
            "pty,raw,echo=0,link=$b",
        ).redirectOutput(ProcessBuilder.Redirect.DISCARD).start()
        process = started
        val ready = CompletableFuture<Unit>()
        thread(isDaemon = true, name = "socat-stderr") {
            try {
                started.errorStream.bufferedReader().forEachLine { line ->
                    if ("starting data transfer loop" in line) ready.complete(Unit)
                    if (" E " in line) System.err.println("[socat] $line")
                }
            } catch (_: IOException) {
                // socat was killed mid-line
            }
            ready.completeExceptionally(IllegalStateException("socat exited (code ${started.waitFor()}) before making the pair"))
        }
        try {
            ready.get(within, TimeUnit.MILLISECONDS)
        } catch (e: TimeoutException) {
            unplug()
            throw IllegalStateException("socat made no pty pair within $within ms", e)
        }
        check(File(a).exists() && File(b).exists()) { "socat said it started but $a or $b is missing" }
    }

    /** Ends socat and waits for it to exit: both ends hang up and their nodes and symlinks go. */
    fun unplug() {
        val running = process ?: return
        process = null
        running.destroy()
        if (!running.waitFor(5, TimeUnit.SECONDS)) {
            running.destroyForcibly()
            running.waitFor(5, TimeUnit.SECONDS)
        }
        // SIGTERM lets socat unlink its symlinks; after a SIGKILL they would dangle.
        File(a).delete()
        File(b).delete()
    }

    override fun close() {
        unplug()
        dir.deleteRecursively()
    }

    companion object {
        /**
         * socat on the PATH. Missing, the serial tests fail (they never skip): CI installs it with
         * tools/system-packages.sh.
         */
        val executable: String by lazy {
            System.getenv("PATH").orEmpty().split(File.pathSeparator)
                .map { File(it, "socat") }
                .firstOrNull { it.canExecute() }?.path
                ?: error("socat is not installed: the serial-link tests need it for pseudo-terminal pairs; run tools/system-packages.sh (as root; CI does)")
        }

        /** A new pair, plugged in. */
        fun pair(): Socat {
            val socat = Socat(Files.createTempDirectory("pod-socat").toFile())
            try {
                socat.plugIn()
            } catch (e: Throwable) {
                socat.close()
                throw e
            }
            return socat
        }
    }
}
