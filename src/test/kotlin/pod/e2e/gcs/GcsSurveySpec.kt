package pod.e2e.gcs

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainInOrder
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.takeWhile
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.runBlocking
import io.kotest.matchers.doubles.plusOrMinus
import org.openqa.selenium.interactions.Actions
import pod.cli.gcs.GcsFleet
import pod.cli.gcs.GcsRequests
import pod.cli.json.EventJson
import pod.cli.json.SurveyPath
import pod.sim.SimFlavor
import pod.sim.SimPlatform
import pod.cli.gcs.SurveySimWorld
import pod.core.units.Location
import pod.core.units.m
import kotlin.math.hypot
import kotlin.time.Duration.Companion.seconds

/**
 * The survey panel, the I-Seed operator's app, in a real browser over a simulated copter in a world
 * with objects to detect: the polygon drawn by clicking the map, the path planned before it is
 * built, the app's states with their event ids, a pause the simulator holds, the photos with
 * detections and the backward route on the map, an abort that brings the copter home.
 */
class GcsSurveySpec : StringSpec({

    "a survey drawn, started, paused and resumed from the page shows its states in order with their event ids; the sim holds while paused, then goes on" {
        withGcs(count = 1, timeScale = 10.0, configure = SurveySimWorld.configure()) { gcs, browser ->
            val home = openOn(gcs, browser)
            drawField(browser, home)
            browser.await("the planned path before building") { browser.findAll("#map polyline.survey-path.preview").firstOrNull() }
            browser.find("#survey-summary").text shouldContain "planned"
            browser.screenshot("survey-planned")

            val build = click(browser, "build", "path_built")
            val start = click(browser, "start", "executing")
            browser.awaitTrue("the forward pass at waypoint 2", 60.seconds) { (state(browser)["waypoint"] as? Long ?: -1) >= 2 }
            val pause = click(browser, "pause", "paused")
            val pausedAt = state(browser)["waypoint"] as Long

            // Paused: the simulated copter itself stops, then stays put over the next 10 s of its own time.
            val sim = gcs.sim[1]
            withTimeout(20.seconds) { sim.state.first { hypot(it.velocityNed.first.metersPerSecond, it.velocityNed.second.metersPerSecond) < 0.2 } }
            val stopped = sim.state.value
            val held = stopped.location
            val drift = withTimeout(20.seconds) {
                sim.state.takeWhile { it.time < stopped.time + 10.seconds }
                    .map { it.location.let { p -> hypot(p.distanceTo(held).meters, (p.altitude - held.altitude).meters) } }.toList()
            }
            withClue("updates while paused: ${drift.size}") { (drift.size >= 10) shouldBe true }
            withClue("drift while paused: $drift") { drift.max() shouldBeLessThanOrEqual 1.0 }
            state(browser)["phase"] shouldBe "paused"

            val resume = click(browser, "resume", "executing")
            withTimeout(30.seconds) { sim.state.first { it.location.distanceTo(held).meters > 5 } } // it goes on
            browser.awaitTrue("a later waypoint after the resume", 60.seconds) {
                val s = state(browser)
                s["pass"] != "forward" || (s["waypoint"] as? Long ?: -1) > pausedAt
            }
            browser.await("a photo with detections on the map", 60.seconds) { browser.findAll("#map circle.survey-photo.detected").firstOrNull() }
            (browser.js("return document.querySelector('#survey-photos li').textContent") as String) shouldContain "waypoint"
            browser.screenshot("survey-detections")
            browser.await("the backward route planned", 90.seconds) { browser.findAll("#map polyline.survey-backward.planned").firstOrNull() }
            browser.awaitTrue("a backward waypoint measured", 60.seconds) { browser.findAll("#map circle.survey-revisit.measured").isNotEmpty() }
            browser.screenshot("survey-backward")
            browser.awaitTrue("finished: landed at home", 120.seconds) { state(browser)["phase"] == "finished" }

            // The commands' event ids grow; each state the app showed carries the latest command's id.
            listOf(build, start, pause, resume).zipWithNext().forEach { (a, b) -> (b > a) shouldBe true }
            val shown = history(browser).map { it["phase"] to it["event_id"] as Long }.distinct()
            shown.shouldContainInOrder(
                "path_built" to build, "executing" to start, "paused" to pause, "executing" to resume, "finished" to resume,
            )
            withClue("no state older than the pause after it: $shown") {
                shown.dropWhile { it != "paused" to pause }.drop(1).takeWhile { it.second == pause }.all { it.first == "paused" } shouldBe true
            }
            val reports = log(browser).filter { it["event"] == "survey_report" }
            reports.any { it["report"] == "holding" && it["event_id"] == pause } shouldBe true
            reports.any { it["report"] == "flying" && it["event_id"] == resume } shouldBe true
            browser.screenshot("survey-finished")
        }
    }

    "abort, confirmed in the page, holds the copter and brings it home" {
        withGcs(count = 1, timeScale = 10.0, configure = SurveySimWorld.configure()) { gcs, browser ->
            val home = openOn(gcs, browser)
            drawField(browser, home)
            browser.await("the planned path") { browser.findAll("#map polyline.survey-path.preview").firstOrNull() }
            click(browser, "build", "path_built")
            click(browser, "start", "executing")
            browser.awaitTrue("the forward pass at waypoint 1", 60.seconds) { (state(browser)["waypoint"] as? Long ?: -1) >= 1 }
            browser.find("#survey-abort").click()
            browser.find("#survey-confirm").isDisplayed shouldBe true
            state(browser)["phase"] shouldBe "executing" // nothing sent before the operator confirms
            val abort = click(browser, "abort-yes", "aborted")
            (state(browser)["event_id"] as Long) shouldBe abort
            val sim = gcs.sim[1]
            withTimeout(30.seconds) { sim.state.first { it.modeName == "RTL" } }
            withTimeout(90.seconds) { sim.state.first { !it.armed } }
            val end = sim.state.value
            withClue("landed ${end.location.distanceTo(end.home)} from home") {
                end.location.distanceTo(end.home).meters shouldBeLessThanOrEqual 3.0
            }
        }
    }

    "bad areas and commands out of turn get clear errors on the page" {
        withGcs(count = 1, timeScale = 10.0) { gcs, browser ->
            val home = openOn(gcs, browser)
            // A bow tie: its edges cross.
            drawField(browser, home, listOf(10 to 10, 50 to 50, 50 to 10, 10 to 50))
            browser.awaitTrue("the planner's reason") { "self-intersecting" in browser.find("#survey-error").text }
            browser.findAll("#map polyline.survey-path.preview").size shouldBe 0
            fun reply(op: String, fields: String) = browser.js("return window.pod.request('$op', $fields)") as Map<*, *>
            val two = reply("survey_plan", "{sysid: 1, area: {polygon: [{lat: 41.1, lon: -8.6}, {lat: 41.1001, lon: -8.6}], height: 20, spacing: 20}}")
            two["ok"] shouldBe false
            (two["error"] as String) shouldContain "at least 3 points"
            val far = reply("survey_plan", "{sysid: 1, area: {polygon: [{lat: 41.2, lon: -8.6}, {lat: 41.2, lon: -8.5}, {lat: 41.3, lon: -8.5}], height: 20, spacing: 20}}")
            (far["error"] as String) shouldContain "too large"
            val start = reply("survey_command", "{sysid: 1, command: 'start'}")
            (start["error"] as String) shouldContain "no survey"
            val unknown = reply("survey_command", "{sysid: 1, command: 'land'}")
            (unknown["error"] as String) shouldContain "not a request"
            val camera = reply("survey_plan", "{sysid: 1, area: {polygon: [${corners(home)}], height: 20, camera: " +
                "{sensor_width_mm: 13.2, sensor_height_mm: 8.8, focal_length_mm: 8.8, image_width: 5472, image_height: 3648, front_overlap: 0.7, side_overlap: 0.6}}}")
            withClue("$camera") { camera["ok"] shouldBe true }
            // A 1" sensor behind 8.8 mm from 20 m sees 30 m across; 60 % side overlap leaves 12 m between tracks.
            (EventJson.decode(camera["detail"] as String) as SurveyPath).spacingM shouldBe (12.0 plusOrMinus 1e-6)
            val nobody = reply("survey_plan", "{sysid: 9, area: {polygon: [], height: 20, spacing: 20}}")
            (nobody["error"] as String) shouldContain "no vehicle 9"
        }
    }

    "stopping the ground station's scope leaves a surveying copter holding where it is" {
        runBlocking {
            val outer = CoroutineScope(SupervisorJob() + Dispatchers.Default)
            val sim = SimPlatform.start(outer, List(1) { SimFlavor.ARDUCOPTER }, 10.0, configure = SurveySimWorld.configure())
            try {
                val work = CoroutineScope(outer.coroutineContext + SupervisorJob(outer.coroutineContext[Job]))
                val fleet = GcsFleet(sim.station, work, "1 simulated copter", 10.0)
                val home = withTimeout(30.seconds) { sim.station.vehicles.first { 1 in it }[1]!!.telemetry.home.filterNotNull().first() }
                val area = "{\"polygon\": [${corners(home)}], \"height\": 20, \"spacing\": 20}"
                withTimeout(30.seconds) { GcsRequests.answer(fleet, "{\"op\": \"survey_build\", \"id\": 1, \"sysid\": 1, \"area\": $area}") }.ok shouldBe true
                withTimeout(30.seconds) { GcsRequests.answer(fleet, "{\"op\": \"survey_command\", \"id\": 2, \"sysid\": 1, \"command\": \"start\"}") }.ok shouldBe true
                val copter = sim[1]
                withTimeout(60.seconds) { copter.state.first { it.relativeAltitude.meters > 15 && it.groundSpeed.metersPerSecond > 1 && it.modeName == "GUIDED" } }
                work.cancel()
                withTimeout(20.seconds) { copter.state.first { it.modeName == "BRAKE" && it.groundSpeed.metersPerSecond < 0.2 } }
                val stopped = copter.state.value
                val drift = withTimeout(20.seconds) {
                    copter.state.takeWhile { it.time < stopped.time + 10.seconds }
                        .map { hypot(it.location.distanceTo(stopped.location).meters, (it.location.altitude - stopped.location.altitude).meters) }.toList()
                }
                withClue("drift after the scope stopped: $drift") { drift.max() shouldBeLessThanOrEqual 1.0 }
                copter.state.value.modeName shouldBe "BRAKE"
            } finally {
                outer.cancel()
                sim.close()
            }
        }
    }
}) {
    private companion object {
        /** The field's corners as the requests' JSON takes them. */
        fun corners(home: Location) = listOf(8 to 8, 8 to 58, 58 to 58, 58 to 8)
            .map { (n, e) -> home.offset(n.m, e.m) }.joinToString(", ") { "{\"lat\": ${it.latitude}, \"lon\": ${it.longitude}}" }

        /** Opens the page, waits for vehicle 1 and its home, selects it and zooms in on the field; returns home. */
        suspend fun openOn(gcs: GcsFixture, browser: GcsBrowser): Location {
            browser.open(gcs.url)
            browser.awaitTrue("vehicle 1 on the map") { browser.findAll("#map g.vehicle").size == 1 }
            val home = withTimeout(30.seconds) { gcs.fleet.vehicle(1).telemetry.home.filterNotNull().first() }
            val field = home.offset(32.m, 32.m)
            browser.js("window.pod.select(1); window.pod.survey.centreOn(arguments[0], arguments[1], 6)", field.latitude, field.longitude)
            return home
        }

        /** Draws a polygon by clicking its corners (metres north and east of [home]) on the map, then closes it. */
        fun drawField(browser: GcsBrowser, home: Location, corners: List<Pair<Int, Int>> = listOf(8 to 8, 8 to 58, 58 to 58, 58 to 8)) {
            browser.find("#survey-draw").click()
            val svg = browser.find("#map")
            val size = svg.size
            for ((n, e) in corners) {
                val p = home.offset(n.m, e.m)
                val at = browser.js("return window.pod.survey.screenOf(arguments[0], arguments[1])", p.latitude, p.longitude) as Map<*, *>
                val x = (at["x"] as Number).toDouble() - size.width / 2.0
                val y = (at["y"] as Number).toDouble() - size.height / 2.0
                Actions(browser.driver).moveToElement(svg, x.toInt(), y.toInt()).click().perform()
            }
            browser.find("#survey-close").click()
        }

        /** Clicks the survey panel's [button] and waits for the app to show [phase]; returns that state's event id. */
        suspend fun click(browser: GcsBrowser, button: String, phase: String): Long {
            browser.find("#survey-$button").click()
            browser.awaitTrue("the survey $phase after $button") { state(browser)["phase"] == phase }
            browser.find("#survey-phase").getAttribute("data-phase") shouldBe phase
            return state(browser)["event_id"] as Long
        }

        fun state(browser: GcsBrowser): Map<*, *> =
            browser.js("const s = window.pod.survey.surveys.get(1); return s && s.state ? s.state : {}") as Map<*, *>

        @Suppress("UNCHECKED_CAST")
        fun history(browser: GcsBrowser): List<Map<*, *>> = browser.js("return window.pod.survey.surveys.get(1).history") as List<Map<*, *>>

        @Suppress("UNCHECKED_CAST")
        fun log(browser: GcsBrowser): List<Map<*, *>> = browser.js("return window.pod.survey.surveys.get(1).log") as List<Map<*, *>>

        infix fun Double.shouldBeLessThanOrEqual(limit: Double) = withClue("$this ≤ $limit") { (this <= limit) shouldBe true }
    }
}
