package pod.e2e.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import org.openqa.selenium.support.ui.Select
import pod.cli.json.PageAction
import kotlin.time.Duration.Companion.seconds

/**
 * The commands panel in a real browser, against simulated ArduCopters on loopback UDP: what the
 * page asks, the simulator does (read from the SimVehicle's own state, not Pod's telemetry), and
 * the page shows the vehicle's answer.
 */
class GcsCommandsSpec : StringSpec({

    "arm and take off from the page: take off asks for confirmation, the sim climbs and the page shows ok" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            browser.open(gcs.url)
            browser.selectVehicle(1)
            browser.find("#commands-panel button[data-command='arm']").click()
            browser.awaitAnswer("arm") shouldStartWith "ok"
            gcs.sim[1].state.value.armed shouldBe true

            val altitude = browser.find("#commands-panel input[data-field='takeoff-alt']")
            altitude.clear()
            altitude.sendKeys("15")
            val takeoff = browser.find("#commands-panel button[data-command='takeoff']")
            takeoff.click()
            takeoff.text shouldBe "confirm take off?"
            gcs.sim[1].height shouldBe (0.0 plusOrMinus 0.5)
            takeoff.click()
            // Disabled until the vehicle's answer comes (it answers once at the height: seconds away).
            takeoff.isEnabled shouldBe false
            browser.awaitTrue("the sim climbing past 5 m") { gcs.sim[1].height > 5 }
            browser.awaitAnswer("takeoff") shouldStartWith "ok"
            takeoff.isEnabled shouldBe true
            gcs.sim[1].height shouldBe (15.0 plusOrMinus 1.0)
            browser.screenshot("commands-takeoff")
        }
    }

    "a command the vehicle refuses shows the autopilot's reason: ArduCopter will not arm in LAND" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            browser.open(gcs.url)
            browser.selectVehicle(1)
            browser.awaitTrue("the vehicle's modes listed") { browser.findAll("#commands-panel select[data-field='mode'] option").size > 5 }
            Select(browser.find("#commands-panel select[data-field='mode']")).selectByValue("LAND")
            browser.find("#commands-panel button[data-command='mode']").click()
            browser.awaitAnswer("mode") shouldStartWith "ok"
            gcs.sim[1].state.value.modeName shouldBe "LAND"

            browser.find("#commands-panel button[data-command='arm']").click()
            val answer = browser.awaitAnswer("arm")
            answer shouldStartWith "refused"
            answer shouldContain "Mode not armable"
            gcs.sim[1].state.value.armed shouldBe false
            browser.find("#commands-panel [data-answer='arm']").getAttribute("class") shouldContain "bad"
            // Logged for every page: the action asked, then its refusal with the reason.
            val logged = ArrayList<pod.cli.json.Event>()
            gcs.fleet.followLog { synchronized(logged) { logged += it } }()
            val arms = synchronized(logged) { logged.filterIsInstance<PageAction>().filter { it.action == "arm" } }
            arms.map { it.outcome } shouldBe listOf("asked", "failed")
            arms.last().detail.orEmpty() shouldContain "Mode not armable"
            browser.screenshot("commands-refused")
        }
    }

    "goto by clicking the map flies the vehicle to about that point, at the height the field defaults to" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            gcs.flyingOnPage(browser, height = 12.0)
            val target = gcs.sim[1].offset(north = 40.0, east = 30.0)
            browser.find("#commands-panel button[data-command='goto']").click()
            browser.find("#commands-panel button[data-command='goto']").text shouldBe "click the map…"
            browser.find("#commands-panel input[data-field='goto-alt']").getAttribute("value") shouldBe "12"
            browser.clickMap(target)
            browser.awaitAnswer("goto") shouldStartWith "ok"
            browser.awaitTrue("the sim within 3 m of the clicked point", 60.seconds) { gcs.sim[1].distanceTo(target) < 3.0 && gcs.sim[1].groundSpeed < 0.5 }
            gcs.sim[1].distanceTo(target) shouldBe (0.0 plusOrMinus 3.0)
            gcs.sim[1].height shouldBe (12.0 plusOrMinus 1.0)
            browser.screenshot("commands-goto")
        }
    }

    "land asks for confirmation first: one click does nothing to the vehicle, the second lands it" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            gcs.flyingOnPage(browser, height = 10.0)
            val land = browser.find("#commands-panel button[data-command='land']")
            land.click()
            land.text shouldBe "confirm land?"
            browser.screenshot("commands-confirm-land")
            // Unconfirmed, the button goes back after a few seconds and nothing was sent.
            browser.awaitTrue("the confirmation to lapse", 10.seconds) { land.text == "Land" }
            gcs.sim[1].state.value.modeName shouldBe "GUIDED"
            gcs.sim[1].height shouldBe (10.0 plusOrMinus 1.0)
            browser.answerOf("land") shouldBe ""

            land.click()
            land.click()
            browser.awaitAnswer("land") shouldStartWith "ok"
            gcs.sim[1].state.value.modeName shouldBe "LAND"
            browser.awaitTrue("the sim descending below 5 m") { gcs.sim[1].height < 5 }
        }
    }

    "pause holds a goto where the vehicle is, and resume flies it on to the point" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            gcs.flyingOnPage(browser, height = 10.0)
            val target = gcs.sim[1].offset(north = 0.0, east = 150.0)
            browser.find("#commands-panel button[data-command='goto']").click()
            browser.clickMap(target)
            browser.awaitAnswer("goto") shouldStartWith "ok"
            browser.awaitTrue("the sim under way") { gcs.sim[1].groundSpeed > 2 }

            browser.find("#commands-panel button[data-command='pause']").click()
            browser.awaitAnswer("pause") shouldStartWith "ok"
            browser.awaitTrue("the sim holding", 30.seconds) { gcs.sim[1].groundSpeed < 0.3 }
            (gcs.sim[1].distanceTo(target) > 30) shouldBe true

            browser.find("#commands-panel button[data-command='resume']").click()
            browser.awaitAnswer("resume") shouldStartWith "ok"
            browser.awaitTrue("the sim at the point after resuming", 60.seconds) { gcs.sim[1].distanceTo(target) < 3 }
        }
    }
})
