package pod.bench.gcs

import kotlinx.coroutines.delay
import kotlinx.coroutines.withTimeout
import org.openqa.selenium.OutputType
import org.openqa.selenium.chrome.ChromeDriver
import org.openqa.selenium.chrome.ChromeDriverService
import org.openqa.selenium.chrome.ChromeOptions
import java.io.File
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes

/**
 * The page in Debian's headless chromium (driven by its chromedriver), measured from inside: every
 * requestAnimationFrame delta (the frame time the operator sees), every long task (over 50 ms, by
 * PerformanceObserver), the batches and events the page took in, and its JavaScript heap.
 */
class GcsPageProbe(private val url: String, private val vehicles: Int) : AutoCloseable {
    private val driver = ChromeDriver(
        ChromeDriverService.Builder().usingDriverExecutable(File("/usr/bin/chromedriver")).usingAnyFreePort().build(),
        ChromeOptions().setBinary("/usr/bin/chromium")
            .addArguments("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu", "--window-size=1400,900"),
    )

    private fun js(script: String): Any? = driver.executeScript(script)

    /** Opens the page and waits until it shows telemetry of every vehicle. */
    suspend fun awaitFleet() {
        driver.get(url)
        withTimeout(2.minutes) {
            while (true) {
                val shown = (js("return window.pod ? [...window.pod.vehicles.values()].filter(v => v.telemetry).length : 0") as Number).toInt()
                if (shown >= vehicles) break
                delay(250.milliseconds)
            }
        }
    }

    /** Starts counting frames, long tasks and batches from now. */
    fun start() {
        js(
            """
            const b = window.__bench = { frames: [], long: [], done: false, t0: performance.now(),
              batches0: pod.stats.batches, events0: pod.stats.events,
              heap0: performance.memory ? performance.memory.usedJSHeapSize : 0 };
            let last = null;
            const frame = (t) => { if (last !== null) b.frames.push(t - last); last = t; if (!b.done) requestAnimationFrame(frame); };
            requestAnimationFrame(frame);
            new PerformanceObserver((list) => { for (const e of list.getEntries()) b.long.push(e.duration); }).observe({ type: "longtask" });
            """,
        )
    }

    /** Stops counting; what the page measured since [start]. */
    fun finish(): BrowserWindow {
        @Suppress("UNCHECKED_CAST")
        val b = js(
            """
            const b = window.__bench; b.done = true;
            return { frames: b.frames, long: b.long, seconds: (performance.now() - b.t0) / 1000,
              batches: pod.stats.batches - b.batches0, events: pod.stats.events - b.events0,
              heap0: b.heap0, heap1: performance.memory ? performance.memory.usedJSHeapSize : 0 };
            """,
        ) as Map<String, Any?>
        val numbers = { key: String -> (b[key] as List<*>).map { (it as Number).toDouble() } }
        File("bench/target/results").mkdirs()
        File("bench/target/results/gcs-$vehicles.png").writeBytes(driver.getScreenshotAs(OutputType.BYTES))
        return BrowserWindow(
            seconds = (b["seconds"] as Number).toDouble(),
            frameMs = numbers("frames"),
            longTaskMs = numbers("long"),
            batches = (b["batches"] as Number).toLong(),
            events = (b["events"] as Number).toLong(),
            heapStartMb = (b["heap0"] as Number).toDouble() / 1e6,
            heapEndMb = (b["heap1"] as Number).toDouble() / 1e6,
        )
    }

    override fun close() = driver.quit()
}

/** What the page measured over one window. */
data class BrowserWindow(
    val seconds: Double,
    val frameMs: List<Double>,
    val longTaskMs: List<Double>,
    val batches: Long,
    val events: Long,
    val heapStartMb: Double,
    val heapEndMb: Double,
)
