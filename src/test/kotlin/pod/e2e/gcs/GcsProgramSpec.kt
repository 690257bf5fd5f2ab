package pod.e2e.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import io.kotest.matchers.string.shouldStartWith
import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import pod.e2e.PodProcess
import pod.e2e.startPod
import pod.e2e.stopPods
import java.io.File
import java.net.InetAddress
import java.net.ServerSocket
import java.nio.file.Files
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * Records, from before the page's own scripts run, the program events its app takes in
 * (`window.pod.on`), so that none sent in the page's first batch is missed.
 */
private const val RECORD_PROGRAM_EVENTS = """
window.programEvents = [];
let app;
Object.defineProperty(window, "pod", {
  configurable: true,
  get() { return app; },
  set(value) {
    app = value;
    for (const kind of ["task_started", "task_done", "picked", "message", "flying"]) value.on(kind, (e) => window.programEvents.push(e));
  },
});
"""

/** The URL `pod` printed in [lines] for the page, once it has. */
private fun urlIn(lines: List<String>): String? = lines.firstNotNullOfOrNull { Regex("ground station: open (http://\\S+)").find(it)?.groupValues?.get(1) }

/** Opens the page of [pod] and returns the program events its app took in once [enough] holds. */
private suspend fun GcsBrowser.programEventsOf(pod: PodProcess, fromErr: Boolean, vehicles: Int, enough: (String) -> Boolean): String {
    val url = await("the page's URL", timeout = 3.minutes) { urlIn(if (fromErr) pod.err.value else pod.out.value) }
    url shouldContain "http://127.0.0.1:"
    driver.executeCdpCommand("Page.addScriptToEvaluateOnNewDocument", mapOf("source" to RECORD_PROGRAM_EVENTS))
    open(url)
    awaitTrue("$vehicles fleet rows") { findAll("#fleet tbody tr").size == vehicles }
    return await("the program's events on the page", timeout = 2.minutes) {
        (js("return JSON.stringify(window.programEvents)") as String).takeIf(enough)
    }
}

/** A program's own page: `pod demo --gcs` and `pod run --gcs` serve the ground station for their fleet. */
class GcsProgramSpec : StringSpec({

    "pod demo --gcs serves the demo's fleet on a page whose log gets the program's tasks, and its terminal output goes on" {
        runBlocking {
            val readers = quietReaders()
            val demo = readers.startPod(listOf("demo", "--gcs", "127.0.0.1:0", "--vehicles", "3", "--time-scale", "60", "--for", "30m", "--map", tempMap()))
            try {
                GcsBrowser().use { browser ->
                    val events = browser.programEventsOf(demo, fromErr = false, vehicles = 3) { "\"listing 4\"" in it && "\"queue tour\"" in it }
                    events shouldContain "\"event\":\"task_started\""
                    browser.screenshot("demo-page")
                }
                // The terminal shows the demo as before: its first line, and the tasks as they start.
                demo.out.value.first() shouldContain "3 simulated drones at 60.0x"
            } finally {
                stopPods(readers, demo)
            }
        }
    }

    "pod run --gcs serves the page for the script's fleet, with the program's events in the log" {
        runBlocking {
            val readers = quietReaders()
            val cache = Files.createTempDirectory("pod-script-cache").toFile()
            val script = File(GcsProgramSpec::class.java.getResource("/scripts/gcs-program.main.kts")!!.toURI()).path
            val run = readers.startPod(
                listOf("run", script, "--sim", "2", "--time-scale", "5", "--gcs", "127.0.0.1:0"),
                environment = mapOf("POD_SCRIPT_CACHE" to cache.path),
            )
            try {
                GcsBrowser().use { browser ->
                    val events = browser.programEventsOf(run, fromErr = true, vehicles = 2) { "gcs script started" in it && "task_started" in it }
                    events shouldContain "\"text\":\"gcs script started\""
                    browser.screenshot("run-page")
                }
            } finally {
                stopPods(readers, run)
                cache.deleteRecursively()
            }
            // Stopped by SIGTERM like any `pod run`: the program cancelled, exit 130.
            run.process.exitValue() shouldBe 130
        }
    }

    "--gcs that cannot be served is bad input (exit 2) before anything runs; without a value it takes the next option as none" {
        runBlocking {
            val readers = quietReaders()
            val taken = ServerSocket(0, 1, InetAddress.getLoopbackAddress())
            val script = File(GcsProgramSpec::class.java.getResource("/scripts/gcs-program.main.kts")!!.toURI()).path
            try {
                val inUse = readers.startPod(listOf("run", script, "--gcs", "127.0.0.1:${taken.localPort}"))
                val notAnAddress = readers.startPod(listOf("demo", "--gcs", "nowhere"))
                // Given bare, --gcs leaves `--for forever` to --for, which refuses it.
                val bare = readers.startPod(listOf("demo", "--gcs", "--for", "forever"))
                for (pod in listOf(inUse, notAnAddress, bare)) pod.exitCode(2.minutes) shouldBe 2
                errorLine(inUse) shouldStartWith "error: cannot serve the ground station on 127.0.0.1:${taken.localPort}"
                errorLine(notAnAddress) shouldContain "not HOST:PORT with a port in 0..65535: 'nowhere'"
                errorLine(bare) shouldContain "forever"
                errorLine(bare) shouldNotContain "HOST:PORT"
            } finally {
                taken.close()
                stopPods(readers)
            }
        }
    }
})

/** The line [pod] wrote to standard error that starts with `error:` or `Error:`, once its reader has it. */
private suspend fun errorLine(pod: PodProcess): String =
    withTimeout(30.seconds) { pod.err.first { lines -> lines.any { it.startsWith("error:", ignoreCase = true) } } }.first { it.startsWith("error:", ignoreCase = true) }

/** Where a process's output readers run: one may end with "Stream closed" when the process exits, not a failure here. */
private fun quietReaders() = CoroutineScope(SupervisorJob() + Dispatchers.IO + CoroutineExceptionHandler { _, _ -> })

private fun tempMap(): String = Files.createTempFile("pod-demo-map", ".svg").toString()
