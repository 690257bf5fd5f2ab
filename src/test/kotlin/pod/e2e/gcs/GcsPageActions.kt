package pod.e2e.gcs

import org.openqa.selenium.interactions.Actions
import pod.core.units.Location
import pod.core.units.m
import pod.sim.SimVehicle
import kotlin.time.Duration.Companion.seconds

// What a person does on the page, for the command and queue specs: pick a vehicle, press a
// button, click or drag on the map at a position. Map positions go through the page's own
// projection (js/map.js `screen`), so a click lands where the page draws that position.

/**
 * Vehicle [sysid] armed and taken off to [height] metres above home through Pod's API (the
 * setup, not what the spec tests), then the page opened with the vehicle selected.
 */
internal suspend fun GcsFixture.flyingOnPage(browser: GcsBrowser, height: Double, sysid: Int = 1) {
    val vehicle = fleet.vehicle(sysid)
    vehicle.action.arm()
    vehicle.action.takeoff(height.m)
    browser.open(url)
    browser.selectVehicle(sysid)
}

/** Selects vehicle [sysid] by clicking its row in the fleet table. */
internal suspend fun GcsBrowser.selectVehicle(sysid: Int) {
    awaitTrue("a fleet row for vehicle $sysid") { findAll("#fleet tbody tr[data-sysid='$sysid']").isNotEmpty() }
    find("#fleet tbody tr[data-sysid='$sysid']").click()
    awaitTrue("vehicle $sysid selected") { js("return window.pod.selected") == sysid.toLong() }
}

/** The text of the first element matching [css], read in one step (the page may redraw it between two). */
internal fun GcsBrowser.textOf(css: String): String = js("const e = document.querySelector(arguments[0]); return e ? e.textContent : ''", css) as String

/** The text of the answer shown under command [name] (`arm`, `takeoff`, …). */
internal fun GcsBrowser.answerOf(name: String): String = textOf("#commands-panel [data-answer='$name']")

/** Waits until command [name]'s answer is no longer "waiting…" and is not blank, and returns it. */
internal suspend fun GcsBrowser.awaitAnswer(name: String, description: String = "the vehicle's answer to $name"): String =
    await(description, 60.seconds) { answerOf(name).takeIf { it.startsWith("ok") || it.startsWith("refused") } }

/** Pixels from the map's top-left corner where the page draws [lat], [lon]. */
@Suppress("UNCHECKED_CAST")
internal fun GcsBrowser.mapPixel(lat: Double, lon: Double): Pair<Double, Double> {
    val script = """
        const done = arguments[arguments.length - 1];
        import(new URL("js/map.js", document.baseURI).href).then((m) => { const s = m.screen(arguments[0], arguments[1]); done([s.x, s.y]); });
    """
    val xy = driver.executeAsyncScript(script, lat, lon) as List<Number>
    return xy[0].toDouble() to xy[1].toDouble()
}

/**
 * Makes the map show [at] as an operator would before clicking there: when it lies outside the
 * view (or within 40 px of its edge), zooms out to the vehicles and [at] together. The page fits
 * its view to the fleet by itself, so a point some way off may not be on screen.
 */
internal fun GcsBrowser.bringIntoView(at: Location) {
    js(
        """
        const [lat, lon] = [arguments[0], arguments[1]];
        const m = window.pod.map, s = m.screen(lat, lon), r = document.getElementById("map").getBoundingClientRect();
        if (s.x >= 40 && s.y >= 40 && s.x <= r.width - 40 && s.y <= r.height - 40) return;
        const points = [...window.pod.vehicles.values()].filter((v) => v.telemetry && v.telemetry.lat != null)
            .map((v) => ({ lat: v.telemetry.lat, lon: v.telemetry.lon }));
        m.fit(points.concat([{ lat, lon }]));
        """,
        at.latitude, at.longitude,
    )
}

/** Zooms the map to show every one of [points] (the page's Fit, on given points). */
internal fun GcsBrowser.fitMap(points: List<Location>) {
    js("window.pod.map.fit(arguments[0].map((p) => ({ lat: p[0], lon: p[1] })))", points.map { listOf(it.latitude, it.longitude) })
}

/** Clicks the map where it draws [at]. */
internal fun GcsBrowser.clickMap(at: Location) {
    bringIntoView(at)
    val (x, y) = mapPixel(at.latitude, at.longitude)
    val svg = find("#map")
    Actions(driver).moveToElement(svg, offsetX(svg, x), offsetY(svg, y)).click().perform()
}

/** Presses the map at [from], drags [pixels] to the right in steps, and releases. */
internal fun GcsBrowser.dragOnMap(from: Location, pixels: Int) {
    val (x, y) = mapPixel(from.latitude, from.longitude)
    val svg = find("#map")
    val drag = Actions(driver).moveToElement(svg, offsetX(svg, x), offsetY(svg, y)).clickAndHold()
    val steps = 5
    repeat(steps) { i -> drag.moveByOffset(pixels * (i + 1) / steps - pixels * i / steps, 0) }
    drag.release().perform()
}

/** The map's scale now, pixels per metre. */
internal fun GcsBrowser.pixelsPerMetre(): Double {
    val script = """
        const done = arguments[arguments.length - 1];
        import(new URL("js/map.js", document.baseURI).href).then((m) => done(m.pixelsPerMetre()));
    """
    return (driver.executeAsyncScript(script) as Number).toDouble()
}

// Selenium 4 measures an offset from the element's centre.
private fun offsetX(svg: org.openqa.selenium.WebElement, x: Double): Int = (x - svg.size.width / 2.0).toInt()
private fun offsetY(svg: org.openqa.selenium.WebElement, y: Double): Int = (y - svg.size.height / 2.0).toInt()

/** Where the simulated vehicle is, by its own state (not Pod's telemetry). */
internal val SimVehicle.here: Location get() = state.value.location

/** Its height above home, metres, by its own state. */
internal val SimVehicle.height: Double get() = state.value.relativeAltitude.meters

/** Its speed over the ground, m/s, by its own state. */
internal val SimVehicle.groundSpeed: Double get() = state.value.velocityNed.let { kotlin.math.hypot(it.first.metersPerSecond, it.second.metersPerSecond) }

/** Horizontal distance from the simulated vehicle to [to], metres. */
internal fun SimVehicle.distanceTo(to: Location): Double = here.copy(altitude = to.altitude).distanceTo(to).meters

/** [north] and [east] metres from where the simulated vehicle is now. */
internal fun SimVehicle.offset(north: Double, east: Double): Location = here.offset(north.m, east.m)
