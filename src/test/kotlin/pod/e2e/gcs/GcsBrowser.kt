package pod.e2e.gcs

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.delay
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import org.openqa.selenium.By
import org.openqa.selenium.JavascriptExecutor
import org.openqa.selenium.OutputType
import org.openqa.selenium.WebElement
import org.openqa.selenium.chrome.ChromeDriver
import org.openqa.selenium.chrome.ChromeDriverService
import org.openqa.selenium.chrome.ChromeOptions
import java.io.File
import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * Debian's headless chromium driven by its chromedriver (the `chromium` and `chromium-driver`
 * packages; tools/system-packages.sh installs them), looking at one `pod gcs` page. Waits are
 * polls of the page's own state (`window.pod`, the DOM) with a timeout, never sleeps.
 */
internal class GcsBrowser(width: Int = 1400, height: Int = 900) : AutoCloseable {
    val driver: ChromeDriver

    init {
        val service = ChromeDriverService.Builder().usingDriverExecutable(File(CHROMEDRIVER)).usingAnyFreePort().build()
        val options = ChromeOptions()
            .setBinary(CHROMIUM)
            .addArguments("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu", "--window-size=$width,$height")
        driver = ChromeDriver(service, options)
    }

    fun open(url: String) = driver.get(url)

    /** Runs [script] in the page (its `return` value back); `window.pod` is the page's app. */
    fun js(script: String, vararg args: Any?): Any? = (driver as JavascriptExecutor).executeScript(script, *args)

    fun find(css: String): WebElement = driver.findElement(By.cssSelector(css))

    fun findAll(css: String): List<WebElement> = driver.findElements(By.cssSelector(css))

    /** Polls [what] every 100 ms until it is non-null, failing with [description] after [timeout]. */
    suspend fun <T : Any> await(description: String, timeout: Duration = 30.seconds, what: () -> T?): T = try {
        withTimeout(timeout) {
            var value: T? = withContext(Dispatchers.IO) { what() }
            while (value == null) {
                delay(100.milliseconds)
                value = withContext(Dispatchers.IO) { what() }
            }
            value
        }
    } catch (e: kotlinx.coroutines.TimeoutCancellationException) {
        throw AssertionError("timed out after $timeout waiting for $description", e)
    }

    /** Polls until [condition] holds. */
    suspend fun awaitTrue(description: String, timeout: Duration = 30.seconds, condition: () -> Boolean) {
        await(description, timeout) { if (condition()) true else null }
    }

    /** Saves what the page shows now as target/gcs-screenshots/[name].png, for a person to look at. */
    fun screenshot(name: String): Path {
        val dir = Path.of("target", "gcs-screenshots").also { Files.createDirectories(it) }
        val png = driver.getScreenshotAs(OutputType.BYTES)
        return dir.resolve("$name.png").also { Files.write(it, png) }
    }

    override fun close() = driver.quit()

    companion object {
        const val CHROMIUM = "/usr/bin/chromium"
        const val CHROMEDRIVER = "/usr/bin/chromedriver"
    }
}
