package pod.e2e.gcs

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import pod.cli.json.Event
import pod.core.PodException

/** `pod gcs` in a real browser: the event log, and a vehicle's STATUSTEXT in the fleet table. */
class GcsEventLogSpec : StringSpec({

    "a refused arm's STATUSTEXT reaches the fleet table and the log, red at its severity" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            browser.open(gcs.url)
            browser.awaitTrue("vehicle 1's row") { MapProbe.cell(browser, 1, "last-text") != null }
            val v = gcs.sim.station.vehicles.value[1]!!
            // ArduCopter will not arm in LAND (ArduCopter/mode.h: ModeLand::allows_arming returns false;
            // AP_Arming_Copter::mandatory_checks then check_failed(true, "Mode not armable"), which
            // AP_Arming sends at MAV_SEVERITY_CRITICAL with "Arm: " while arming), with COMMAND_ACK FAILED.
            v.action.setMode("LAND")
            val refusal = shouldThrow<PodException> { v.action.arm() }
            refusal.message!! shouldContain "Mode not armable"

            browser.awaitTrue("the text in vehicle 1's row, red") {
                MapProbe.cell(browser, 1, "last-text") == ("Arm: Mode not armable" to "bad")
            }
            browser.find("#fleet tr[data-sysid=\"1\"] td[data-column=\"last-text\"]").getAttribute("title") shouldBe "CRITICAL: Arm: Mode not armable"
            val line = browser.await("the text in the log") {
                browser.findAll("#events li.ev-vehicle_text").firstOrNull { "Mode not armable" in it.text }
            }
            line.getAttribute("class")!! shouldContain "bad"
            line.text shouldContain "V1"
            line.text shouldContain "says [CRITICAL] Arm: Mode not armable"
            MapProbe.cell(browser, 1, "mode")?.first shouldBe "LAND"
            browser.screenshot("statustext-arm-refused")
        }
    }

    "the log shows program events as coloured lines per vehicle, replays what came before the page, filters to the selected vehicle" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            gcs.fleet.logEvent(Event.Message(0.0, "logged before the page opened"))
            browser.open(gcs.url)
            browser.awaitTrue("the earlier line, marked as before") {
                browser.findAll("#events li.before").any { "logged before the page opened" in it.text } &&
                    browser.findAll("#events li.separator").size == 1
            }
            gcs.fleet.logEvent(Event.TaskStarted(1.0, 7, 0, "survey north", listOf(1)))
            gcs.fleet.logEvent(Event.TaskStarted(1.5, 8, 0, "ferry", listOf(2)))
            gcs.fleet.logEvent(Event.Warning("battery of vehicle 1 at 25%"))
            gcs.fleet.logEvent(Event.TaskFailed(2.0, 7, "survey north", "vehicle 1 lost"))
            gcs.fleet.logEvent(Event.TaskDone(3.0, 8, "ferry"))
            // A kind the log has no words for (another panel's) is shown as its JSON.
            gcs.fleet.logEvent(Event.Listening("udpin:0.0.0.0:14550", 14550))
            browser.awaitTrue("six more lines") { browser.findAll("#events li.ev").size >= 8 }
            browser.findAll("#events li.ev-listening").single().text shouldContain "listening: {\"address\":\"udpin:0.0.0.0:14550\",\"port\":14550}"

            fun line(kind: String) = browser.findAll("#events li.ev-$kind").last()
            line("task_failed").let {
                it.getAttribute("class")!! shouldContain "bad"
                it.text shouldContain "V1"
                it.text shouldContain "task 7 “survey north” FAILED: vehicle 1 lost"
            }
            line("warning").getAttribute("class")!! shouldContain "warn"
            line("task_done").let {
                it.getAttribute("class")!! shouldContain "good"
                it.text shouldContain "V2"
            }

            browser.js("pod.select(1)")
            browser.find("#events-selected-only").click()
            browser.awaitTrue("only vehicle 1's lines shown") {
                val shown = shownLines(browser)
                shown.isNotEmpty() && shown.all { it.split(" ").contains("1") }
            }
            shownLines(browser).size shouldBe 3 // found, task 7 started, task 7 failed
            browser.screenshot("event-log-vehicle-1-only")
            browser.find("#events-selected-only").click()
            browser.awaitTrue("every line shown again") { shownLines(browser).size == browser.findAll("#events li").size }
        }
    }

    "the log keeps its last 1000 lines and follows the newest unless the operator scrolled up" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            browser.open(gcs.url)
            // The first batch comes once the feeds follow the log: from then on every event reaches the page.
            browser.awaitTrue("the page's first batch") { (browser.js("return pod.stats.batches") as Number).toInt() > 0 }
            repeat(1100) { gcs.fleet.logEvent(Event.Message(it.toDouble(), "message $it")) }
            browser.awaitTrue("the last message shown") { lastLine(browser) == "message 1099" }
            (browser.js("return document.getElementById('events').childElementCount") as Number).toInt() shouldBe 1000
            browser.awaitTrue("the panel at its bottom") { distanceFromBottom(browser) < 24 }

            browser.js("document.getElementById('events-panel').scrollTop = 0")
            browser.awaitTrue("scrolled up") { distanceFromBottom(browser) > 100 }
            repeat(5) { gcs.fleet.logEvent(Event.Message(2000.0 + it, "later $it")) }
            browser.awaitTrue("the later lines added") { lastLine(browser) == "later 4" }
            (browser.js("return document.getElementById('events-panel').scrollTop") as Number).toDouble() shouldBeLessThan 1.0
        }
    }
})

/** The vehicles (`data-vehicles`) of each log line the page lays out (one hidden has no boxes). */
@Suppress("UNCHECKED_CAST")
private fun shownLines(browser: GcsBrowser): List<String> =
    browser.js("return [...document.querySelectorAll('#events li')].filter((li) => li.getClientRects().length > 0).map((li) => li.dataset.vehicles)") as List<String>

private fun lastLine(browser: GcsBrowser): String? =
    browser.js("const li = document.querySelector('#events li.ev:last-child .what'); return li ? li.textContent : null") as String?

private fun distanceFromBottom(browser: GcsBrowser): Double =
    (browser.js("const p = document.getElementById('events-panel'); return p.scrollHeight - p.scrollTop - p.clientHeight") as Number).toDouble()
