package pod.e2e.gcs

/**
 * What the page's map shows for one vehicle, read from the DOM: where its marker is drawn (centre
 * of its box, in pixels from the map's corner), the position it carries, its track, its label.
 */
internal data class MarkerView(
    val lat: Double,
    val lon: Double,
    /** Centre of the marker's box on the map, pixels. */
    val x: Double,
    val y: Double,
    /** Where the map's projection puts (lat, lon), pixels: the marker must be drawn there. */
    val expectedX: Double,
    val expectedY: Double,
    val trackPoints: Int,
    /** Metres from the track's last point to the marker's position. */
    val trackEndOffset: Double?,
    val label: String,
    val labelShown: Boolean,
    val classes: String,
)

internal object MapProbe {
    private const val MARKER = """
        const sysid = arguments[0];
        const g = document.querySelector(`#map g.vehicle[data-sysid="${'$'}{sysid}"]`);
        if (!g || g.dataset.lat === undefined) return null;
        const line = document.querySelector(`#map polyline.track[data-sysid="${'$'}{sysid}"]`);
        const label = document.querySelector(`#map text.label[data-sysid="${'$'}{sysid}"]`);
        const lat = +g.dataset.lat, lon = +g.dataset.lon;
        const w = pod.map.world(lat, lon), s = pod.map.screen(lat, lon);
        const n = line.points.numberOfItems, last = n ? line.points.getItem(n - 1) : null;
        const body = g.querySelector(".body").getBoundingClientRect(), m = document.getElementById("map").getBoundingClientRect();
        return { lat, lon, x: body.left + body.width / 2 - m.left, y: body.top + body.height / 2 - m.top, ex: s.x, ey: s.y,
          points: n, end: last ? Math.hypot(last.x - w.x, last.y - w.y) : null, label: label.textContent,
          shown: label.style.display !== "none", classes: g.getAttribute("class") };
    """

    fun marker(browser: GcsBrowser, sysid: Int): MarkerView? {
        @Suppress("UNCHECKED_CAST")
        val m = browser.js(MARKER, sysid) as Map<String, Any?>? ?: return null
        fun d(key: String) = (m[key] as Number).toDouble()
        return MarkerView(
            d("lat"), d("lon"), d("x"), d("y"), d("ex"), d("ey"), (m["points"] as Number).toInt(),
            (m["end"] as Number?)?.toDouble(), m["label"] as String, m["shown"] as Boolean, m["classes"] as String,
        )
    }

    /** The boxes of the labels shown, [left, top, right, bottom] in page pixels. */
    @Suppress("UNCHECKED_CAST")
    fun labelBoxes(browser: GcsBrowser): List<List<Double>> = (
        browser.js(
            """return [...document.querySelectorAll("#map text.label")].filter((t) => t.style.display !== "none")
                 .map((t) => { const r = t.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; });""",
        ) as List<List<Number>>
        ).map { box -> box.map { it.toDouble() } }

    /** Whether two [labelBoxes] overlap. */
    fun overlap(a: List<Double>, b: List<Double>): Boolean = a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]

    /** The pairs of [labelBoxes] that overlap (none, when the labels are laid out right). */
    fun overlapping(boxes: List<List<Double>>): List<Pair<List<Double>, List<Double>>> =
        boxes.indices.flatMap { i -> (i + 1 until boxes.size).filter { j -> overlap(boxes[i], boxes[j]) }.map { j -> boxes[i] to boxes[j] } }

    /** The scale bar: its length in pixels, the metres it stands for, its text; and the map's pixels per metre. */
    @Suppress("UNCHECKED_CAST")
    fun scaleBar(browser: GcsBrowser): Map<String, Any?> = browser.js(
        """const line = document.querySelector("#map .scale-bar line"), text = document.querySelector("#map .scale-bar text");
           return { px: +line.getAttribute("x2") - +line.getAttribute("x1"), metres: +line.dataset.metres, text: text.textContent, ppm: pod.map.pixelsPerMetre() };""",
    ) as Map<String, Any?>

    /** The text of a fleet-table cell: row [sysid], column [column] (`link`, `last-text`…), and its classes. */
    fun cell(browser: GcsBrowser, sysid: Int, column: String): Pair<String, String>? {
        @Suppress("UNCHECKED_CAST")
        val r = browser.js(
            """const td = document.querySelector(`#fleet tr[data-sysid="${'$'}{arguments[0]}"] td[data-column="${'$'}{arguments[1]}"]`);
               return td ? [td.textContent, td.className] : null;""",
            sysid, column,
        ) as List<String>? ?: return null
        return r[0] to r[1]
    }
}
