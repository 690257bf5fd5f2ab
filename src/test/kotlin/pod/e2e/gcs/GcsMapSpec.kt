package pod.e2e.gcs

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import kotlinx.coroutines.launch
import org.openqa.selenium.By
import pod.core.units.Location
import pod.core.units.m
import kotlin.math.abs
import kotlin.math.hypot
import kotlin.time.Duration.Companion.seconds

/** `pod gcs` in a real browser: the map follows the fleet (markers, labels, tracks, homes, lost vehicles, fit, scale). */
class GcsMapSpec : StringSpec({

    "a flying vehicle's marker, label and track follow it; every home is drawn; labels of parked vehicles do not overlap" {
        withGcs(count = 3, timeScale = 5.0) { gcs, browser ->
            browser.open(gcs.url)
            browser.awaitTrue("three markers and three homes") {
                browser.findAll("#map g.vehicle").size == 3 && browser.findAll("#map g.home").size == 3
            }
            for (sim in gcs.sim.simulated) {
                val id = sim.config.systemId
                val home = browser.find("#map g.home[data-sysid=\"$id\"]")
                val drawn = Location(home.getAttribute("data-lat")!!.toDouble(), home.getAttribute("data-lon")!!.toDouble(), 0.m)
                drawn.distanceTo(sim.config.home.copy(altitude = 0.m)).meters shouldBeLessThan 1.0
            }
            // Parked 5 m apart: every label shown, none over another.
            val labels = MapProbe.labelBoxes(browser)
            labels shouldHaveSize 3
            MapProbe.overlapping(labels) shouldBe emptyList()

            val v1 = gcs.sim.station.vehicles.value[1]!!
            val v2 = gcs.sim.station.vehicles.value[2]!!
            val start = MapProbe.marker(browser, 1)!!
            val target1 = v1.telemetry.position.value!!.location.let { it.offset(north = 60.m, east = 40.m, up = 10.m) }
            val target2 = v2.telemetry.position.value!!.location.let { it.offset(north = (-30).m, east = (-50).m, up = 15.m) }
            gcs.scope.launch { v1.action.getAirborne(10.m); v1.action.goto(target1) }
            gcs.scope.launch { v2.action.getAirborne(15.m); v2.action.goto(target2) }

            val arrived = browser.await("vehicle 1's marker at its goto target", 90.seconds) {
                MapProbe.marker(browser, 1)?.takeIf { Location(it.lat, it.lon, 0.m).distanceTo(target1.copy(altitude = 0.m)).meters < 2.0 }
            }
            // Drawn where the projection puts the position it carries, moved across the screen, with a track ending at it.
            arrived.x shouldBe (arrived.expectedX plusOrMinus 2.0)
            arrived.y shouldBe (arrived.expectedY plusOrMinus 2.0)
            hypot(arrived.x - start.x, arrived.y - start.y) shouldBeGreaterThan 30.0
            (arrived.trackPoints > 20) shouldBe true
            arrived.trackEndOffset!! shouldBeLessThan 1.0
            browser.awaitTrue("vehicle 1's label says GUIDED at about 10 m") {
                Regex("""^1 GUIDED (\d+\.\d) m \d+%$""").find(MapProbe.marker(browser, 1)!!.label)
                    ?.let { abs(it.groupValues[1].toDouble() - 10.0) < 1.5 } == true
            }
            browser.await("vehicle 2 at its goto target", 90.seconds) {
                MapProbe.marker(browser, 2)?.takeIf { Location(it.lat, it.lon, 0.m).distanceTo(target2.copy(altitude = 0.m)).meters < 2.0 }
            }

            browser.find("#map-fit").click()
            browser.awaitTrue("every marker inside the map after Fit") { markersInside(browser, 3) }
            // Clicking a marker selects its vehicle on the map and in the table.
            browser.find("#map g.vehicle[data-sysid=\"1\"] .body").click()
            browser.awaitTrue("vehicle 1 selected") {
                MapProbe.marker(browser, 1)!!.classes.contains("selected") &&
                    browser.find("#fleet tr[data-sysid=\"1\"]").getAttribute("class")!!.contains("selected")
            }
            browser.findAll("#map-tiles-note") shouldHaveSize 0
            browser.screenshot("fleet-two-flying-with-tracks")
        }
    }

    "a vehicle that stops is shown LOST in the table, on the map and in the log, where it was last heard" {
        withGcs(count = 2, timeScale = 5.0) { gcs, browser ->
            browser.open(gcs.url)
            browser.awaitTrue("two markers") { browser.findAll("#map g.vehicle").size == 2 }
            val before = browser.await("vehicle 2's marker") { MapProbe.marker(browser, 2) }
            MapProbe.cell(browser, 2, "link") shouldBe ("ok" to "good")

            gcs.sim[2].stop()

            browser.awaitTrue("vehicle 2's row LOST", 20.seconds) {
                browser.find("#fleet tr[data-sysid=\"2\"]").getAttribute("class")!!.contains("lost") &&
                    MapProbe.cell(browser, 2, "link")?.first == "LOST"
            }
            val lost = browser.await("vehicle 2's marker marked lost") { MapProbe.marker(browser, 2)?.takeIf { "lost" in it.classes } }
            lost.label shouldContain "LOST"
            lost.labelShown shouldBe true
            lost.lat shouldBe before.lat
            lost.lon shouldBe before.lon
            browser.awaitTrue("a red lost line about V2 in the log") {
                browser.findAll("#events li.ev-lost.bad").any { it.findElement(By.cssSelector(".who")).text == "V2" }
            }
            MapProbe.cell(browser, 1, "link")?.first shouldBe "ok"
            MapProbe.marker(browser, 1)!!.classes shouldNotContain "lost"
            browser.screenshot("vehicle-2-lost")
        }
    }

    "Fit shows vehicles kilometres apart, and the scale bar and the markers' spacing match the ground at every zoom" {
        // Vehicle 2 boots 2 km north and 2.5 km east of the others.
        val far: (pod.sim.SimVehicleConfig) -> pod.sim.SimVehicleConfig = { c -> if (c.systemId == 2) c.copy(home = c.home.offset(north = 2000.m, east = 2500.m)) else c }
        withGcs(count = 2, timeScale = 5.0, configure = far) { gcs, browser ->
            browser.open(gcs.url)
            browser.awaitTrue("two markers") { browser.findAll("#map g.vehicle").size == 2 }
            browser.js("pod.map.centreOn(arguments[0], arguments[1], 20)", gcs.sim[1].config.home.latitude, gcs.sim[1].config.home.longitude)
            browser.awaitTrue("vehicle 2 out of view when zoomed in on vehicle 1") { !markersInside(browser, 2) }
            browser.find("#map-fit").click()
            browser.awaitTrue("both markers inside the map after Fit") { markersInside(browser, 2) }
            val ground = gcs.sim[1].config.home.distanceTo(gcs.sim[2].config.home.copy(altitude = gcs.sim[1].config.home.altitude)).meters
            var previous = 0.0
            for (step in 0..3) {
                // The wheel redraws at the next frame: wait for it; a scale bar that does not match the zoom never passes.
                val scale = browser.await("the scale bar drawn for the zoom after step $step") {
                    MapProbe.scaleBar(browser).takeIf { bar ->
                        val ppm = (bar["ppm"] as Number).toDouble()
                        ppm > previous * 1.5 && abs((bar["px"] as Number).toDouble() - (bar["metres"] as Number).toDouble() * ppm) < 0.5
                    }
                }
                val ppm = (scale["ppm"] as Number).toDouble()
                val metres = (scale["metres"] as Number).toDouble()
                previous = ppm
                scale["text"] shouldBe if (metres >= 1000) "${(metres / 1000).toString().removeSuffix(".0")} km" else "${metres.toInt()} m"
                val a = MapProbe.marker(browser, 1)!!
                val b = MapProbe.marker(browser, 2)!!
                hypot(a.expectedX - b.expectedX, a.expectedY - b.expectedY) / ppm shouldBe (ground plusOrMinus ground * 0.01)
                // Zoom in around vehicle 1 with the wheel, as an operator does.
                browser.js(
                    """const svg = document.getElementById("map"), r = svg.getBoundingClientRect(), s = pod.map.screen(arguments[0], arguments[1]);
                       svg.dispatchEvent(new WheelEvent("wheel", { deltaY: -400, clientX: r.left + s.x, clientY: r.top + s.y, bubbles: true, cancelable: true }));""",
                    a.lat, a.lon,
                )
            }
            browser.screenshot("fit-zoomed-in-on-vehicle-1-of-two-3km-apart")
        }
    }

    "250 vehicles side by side: a row and a marker each, and the labels shown never overlap (time per batch printed)" {
        withGcs(count = 1, timeScale = 5.0) { gcs, browser ->
            browser.open(gcs.url)
            browser.await("vehicle 1's marker") { MapProbe.marker(browser, 1) }
            // 249 more vehicles in the page's fleet state, 5 m apart, moved a little per "batch" as telemetry would.
            @Suppress("UNCHECKED_CAST")
            val times = browser.js(
                """const base = pod.vehicles.get(1).telemetry, times = [];
                   for (let i = 2; i <= 250; i++) pod.vehicles.set(i, { sysid: i, type: "QUADROTOR", autopilot: "ARDUPILOT", lost: i % 50 === 0, home: null, status: null, telemetry: base });
                   for (let batch = 0; batch < 30; batch++) {
                     for (let i = 2; i <= 250; i++) {
                       const v = pod.vehicles.get(i);
                       v.telemetry = { ...base, sysid: i, lat: base.lat + (i % 16) * 0.000045 + batch * 0.000001, lon: base.lon + Math.floor(i / 16) * 0.00006, heading: (i * 7 + batch) % 360 };
                     }
                     const t0 = performance.now();
                     pod.select(pod.selected); // runs every panel's after-batch redraw, as a batch does
                     times.push(performance.now() - t0);
                   }
                   pod.map.fitFleet();
                   return times;""",
            ) as List<Number>
            val sorted = times.map { it.toDouble() }.sorted()
            println("GcsMapSpec: 250 vehicles, page work per batch: median %.1f ms, max %.1f ms".format(sorted[sorted.size / 2], sorted.last()))
            browser.findAll("#fleet tbody tr").size shouldBe 250
            browser.findAll("#map g.vehicle").size shouldBe 250
            browser.findAll("#map g.vehicle.lost").size shouldBe 5
            val labels = MapProbe.labelBoxes(browser)
            MapProbe.overlapping(labels) shouldBe emptyList()
            val hidden = 250 - labels.size
            if (hidden > 0) browser.find("#map-note").text shouldBe "$hidden labels hidden: zoom in"
            browser.screenshot("fleet-250-vehicles-decluttered-labels")
        }
    }
})

/** Whether the first [count] vehicles' markers are all drawn inside the map's area. */
private fun markersInside(browser: GcsBrowser, count: Int): Boolean {
    val size = browser.js("""const r = document.getElementById("map").getBoundingClientRect(); return [r.width, r.height];""") as List<*>
    val (w, h) = size.map { (it as Number).toDouble() }
    return (1..count).all { id -> MapProbe.marker(browser, id)?.let { it.x in 0.0..w && it.y in 0.0..h } == true }
}
