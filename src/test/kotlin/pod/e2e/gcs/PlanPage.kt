package pod.e2e.gcs

import kotlinx.coroutines.runBlocking
import pod.mavlink.MavFrames
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.plan.FenceCircle
import pod.mavlink.plan.FencePolygon
import pod.mavlink.plan.PlanGeoFence
import pod.mavlink.plan.PlanPoint
import pod.mavlink.plan.PlanPosition
import pod.mavlink.plan.QgcPlan
import pod.sim.SimFlavor
import pod.sim.SimVehicleConfig
import kotlin.math.cos
import kotlin.time.Duration.Companion.seconds

// What the plans specs share: plans near the simulated vehicles' home, and the page's plan panel.

private val HOME = SimVehicleConfig.DEFAULT_HOME

/** The position [north] and [east] metres from the simulated home, rounded to MAVLink's 10⁻⁷°. */
internal fun nearHome(north: Double, east: Double): PlanPoint {
    val lat = HOME.latitude + north / 111_320.0
    val lon = HOME.longitude + east / (111_320.0 * cos(Math.toRadians(HOME.latitude)))
    return PlanPoint(Math.round(lat * 1e7) / 1e7, Math.round(lon * 1e7) / 1e7)
}

/** A mission item of [command] at [at] (no position when null), [z] metres above home. */
internal fun item(seq: Int, command: Int, at: PlanPoint?, z: Float = 30f, frame: Int = MavFrames.GLOBAL_RELATIVE_ALT) = MissionItem(
    seq = seq, frame = frame, command = command,
    x = at?.let { Math.round(it.latitude * 1e7).toInt() } ?: 0,
    y = at?.let { Math.round(it.longitude * 1e7).toInt() } ?: 0,
    z = z, missionType = MissionType.MISSION,
)

/**
 * A survey-like plan around home: takeoff, four corners of a 120 m square, a region of interest,
 * return to launch; a keep-in polygon, a keep-out circle and one rally point.
 */
internal fun squarePlan(): QgcPlan {
    val corners = listOf(nearHome(60.0, -60.0), nearHome(60.0, 60.0), nearHome(-60.0, 60.0), nearHome(-60.0, -60.0))
    val mission = listOf(item(0, 22, nearHome(0.0, 0.0), 20f)) +
        corners.mapIndexed { i, at -> item(i + 1, 16, at) } +
        item(5, 201, nearHome(0.0, 100.0), 0f) + // DO_SET_ROI: a place, not a leg of the path
        item(6, 20, null, 0f) // RETURN_TO_LAUNCH
    return QgcPlan(
        mission = mission,
        geoFence = PlanGeoFence(
            polygons = listOf(FencePolygon(true, listOf(nearHome(150.0, -150.0), nearHome(150.0, 150.0), nearHome(-150.0, 150.0), nearHome(-150.0, -150.0)))),
            circles = listOf(FenceCircle(false, nearHome(-100.0, 0.0), 25.0)),
        ),
        rallyPoints = listOf(PlanPosition(nearHome(-80.0, -100.0).latitude, nearHome(-80.0, -100.0).longitude, 25.0)),
        firmwareType = 12,
        vehicleType = 2,
    )
}

/** Drops a file named [name] holding [text] on the element [selector], as a person dragging it from a file manager does. */
internal fun GcsBrowser.drop(selector: String, name: String, text: String) {
    js(
        """
        const [selector, name, text] = arguments;
        const data = new DataTransfer();
        data.items.add(new File([text], name));
        const target = document.querySelector(selector);
        for (const type of ["dragenter", "dragover", "drop"]) {
          target.dispatchEvent(new DragEvent(type, { dataTransfer: data, bubbles: true, cancelable: true }));
        }
        """.trimIndent(),
        selector, name, text,
    )
}

/** The plans panel's outcome line once it is no longer busy: (kind, text). */
internal suspend fun GcsBrowser.planOutcome(): Pair<String, String> = await("the plans panel's outcome", timeout = 90.seconds) {
    val kind = find("#plan-status").getAttribute("data-kind")
    if (kind == "good" || kind == "bad") kind to find("#plan-status").text else null
}

/** Opens the page, waits for [count] fleet rows and selects vehicle [sysid] by clicking its row. */
internal suspend fun GcsBrowser.openAndSelect(url: String, count: Int, sysid: Int) {
    open(url)
    awaitTrue("$count fleet rows") { findAll("#fleet tbody tr").size == count }
    find("#fleet tbody tr[data-sysid='$sysid']").click()
    awaitTrue("vehicle $sysid selected") { js("return window.pod.selected") == sysid.toLong() }
}

/** A fixture of the given [flavors] (system ids from 1) with a browser. */
internal fun withGcsOf(
    flavors: List<SimFlavor>,
    timeScale: Double = 5.0,
    configure: (SimVehicleConfig) -> SimVehicleConfig = { it },
    block: suspend (GcsFixture, GcsBrowser) -> Unit,
) = runBlocking {
    GcsFixture.start(flavors.size, timeScale, flavors = flavors, configure = configure).use { gcs ->
        GcsBrowser().use { browser -> block(gcs, browser) }
    }
}
