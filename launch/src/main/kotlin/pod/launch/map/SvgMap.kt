package pod.launch.map

import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.survey.SurveyPlan
import pod.core.survey.SurveyWaypoint
import pod.core.units.Location
import pod.launch.map.MapFrame.Companion.fmt
import pod.core.units.m
import kotlin.math.max

/**
 * Draws on one SVG map, north up, with a scale bar and a legend: planned missions (dashed, a dot
 * per step) and flown tracks (solid), one colour per vehicle; a plan's fence zones (inclusion
 * outlined green, exclusion filled red), rally points and mission; and a survey's layers — its
 * polygon, the forward path (photographed track legs solid, turnaround and transit legs dotted, a
 * dot per photo waypoint), the waypoints that detected something (rings), objects on the ground
 * (crosses) and the backward path (numbered in the order flown). The canvas is fitted to
 * everything drawn.
 *
 * Each layer is an SVG group whose id names it (`fence`, `survey-area`, `plan-mission`, `planned`,
 * `flown` (with each vehicle's name at its track's end), `forward-path`, `photo-waypoints`,
 * `rally`, `objects`, `detections`, `backward-path`, `homes`, `legend`), so a reader or a test can
 * pick it out; the legend's entries name the layer they explain in `data-layer`.
 */
internal class SvgMap(private val maxWidth: Int = 900, private val maxHeight: Int = 700) {
    private class Line(val vehicleId: Int, val label: String, val points: List<Location>, val planned: Boolean)

    private val lines = mutableListOf<Line>()
    private val vehicleNames = sortedMapOf<Int, String>()
    private var area: List<Location> = emptyList()
    private var forward: List<SurveyWaypoint> = emptyList()
    private var detections: List<Pair<Int, Location>> = emptyList()
    private var objects: List<Location> = emptyList()
    private var backward: List<Pair<Int, Location>> = emptyList()
    private val homes = sortedMapOf<Int, Location>()
    private class Zone(val inclusion: Boolean, val vertices: List<Location>, val centre: Location?, val radius: Double, val label: String)
    private val zones = mutableListOf<Zone>()
    private val rally = mutableListOf<Location>()
    private val plans = mutableListOf<Pair<String, List<Location>>>()
    private val planNumbers = mutableMapOf<Int, List<String>>()

    /** Adds [mission]'s path as planned for vehicle [vehicleId]. */
    internal fun planned(vehicleId: Int, mission: Mission) {
        planned(vehicleId, mission.name, mission.steps.filterIsInstance<MissionStep.Navigation>().map { it.location })
    }

    /** Adds a path planned for vehicle [vehicleId], called [label]. */
    internal fun planned(vehicleId: Int, label: String, points: List<Location>) {
        if (points.isNotEmpty()) lines += Line(vehicleId, label, points, planned = true)
    }

    /** Adds a flown track of vehicle [vehicleId], called [name]. */
    internal fun flown(vehicleId: Int, name: String, points: List<Location>) {
        if (points.size >= 2) {
            lines += Line(vehicleId, name, points, planned = false)
            vehicleNames[vehicleId] = name
        }
    }

    /** Marks the home of vehicle [vehicleId]. */
    internal fun home(vehicleId: Int, at: Location) {
        homes[vehicleId] = at
    }

    /**
     * Adds a mission path from a plan, not any one vehicle's: dashed, a dot per item, numbered by
     * [numbers] (the items' numbers, one per point; null: 1, 2, 3… in order).
     */
    internal fun plannedPath(label: String, points: List<Location>, numbers: List<String>? = null) {
        if (points.size < 2) return
        planNumbers[plans.size] = numbers?.takeIf { it.size == points.size } ?: points.indices.map { (it + 1).toString() }
        plans += label to points
    }

    /** Adds a fence polygon (vertices, not closed): an area to stay inside when [inclusion], else one to keep out of. */
    internal fun fence(vertices: List<Location>, inclusion: Boolean, label: String) {
        zones += Zone(inclusion, vertices, null, 0.0, label)
    }

    /** Adds a circular fence of [radius] metres around [centre]. */
    internal fun fenceCircle(centre: Location, radius: Double, inclusion: Boolean, label: String) {
        zones += Zone(inclusion, emptyList(), centre, radius, label)
    }

    /** Marks a rally point. */
    internal fun rallyPoint(at: Location) {
        rally += at
    }

    /** Sets the surveyed polygon (its vertices, not closed). */
    internal fun surveyArea(polygon: List<Location>) {
        area = polygon
    }

    /** Sets the forward path: [plan]'s waypoints in flying order. */
    internal fun forwardPath(plan: SurveyPlan) {
        forward = plan.waypoints
    }

    /** Marks the waypoints of [plan] at [indices] as having detected something. */
    internal fun detections(plan: SurveyPlan, indices: List<Int>) {
        detections = indices.map { it to plan.waypoints[it].location }
    }

    /** Sets where objects on the ground are known to lie. */
    internal fun objects(locations: List<Location>) {
        objects = locations
    }

    /** Sets the backward path: the waypoints of [plan] at [order], in the order flown. */
    internal fun backwardPath(plan: SurveyPlan, order: List<Int>) {
        backward = order.map { it to plan.waypoints[it].location }
    }

    /** The SVG document. */
    internal fun render(title: String): String {
        val legend = legendEntries()
        val legendWidth = if (legend.isEmpty()) 0.0 else Legend.WIDTH
        val zoneExtent = zones.flatMap { z ->
            z.vertices + listOfNotNull(z.centre).flatMap { c -> listOf(c.offset(z.radius.m, z.radius.m), c.offset((-z.radius).m, (-z.radius).m)) }
        }
        val content = area + forward.map { it.location } + lines.flatMap { it.points } + objects + homes.values +
            zoneExtent + rally + plans.flatMap { it.second }
        val frame = MapFrame(content, maxWidth - 2 * MARGIN - legendWidth, maxHeight - TOP - BOTTOM)
        val width = max(MARGIN + frame.width + MARGIN + legendWidth, MIN_WIDTH)
        val height = max(TOP + frame.height + BOTTOM, TOP + Legend.height(legend) + MARGIN)
        val px = Projection { l -> frame.pixel(l).let { (x, y) -> MARGIN + x to TOP + y } }
        return buildString {
            val w = fmt(width)
            val h = fmt(height)
            appendLine("""<svg xmlns="http://www.w3.org/2000/svg" width="$w" height="$h" viewBox="0 0 $w $h">""")
            appendLine("""<rect width="100%" height="100%" fill="#fbfbf8"/>""")
            appendLine("""<text x="${fmt(MARGIN)}" y="24" font-family="sans-serif" font-size="16">${escape(title)}</text>""")
            if (area.isNotEmpty()) {
                appendLine("""<g id="survey-area"><polygon points="${px.points(area)}" fill="$AREA" fill-opacity="0.2" stroke="$AREA" stroke-width="1.5"/></g>""")
            }
            zoneLayers(px, frame.pixelsPerMetre)
            // Tracks go under the forward path: a survey's flown track follows the plan, and the
            // plan (with its photo dots) must stay readable on top of it.
            vehicleLayers(px)
            forwardLayers(px)
            markerLayers(px)
            labelLayers(px)
            Legend.render(this, legend, width - legendWidth, TOP)
            val barMetres = frame.scaleBarMetres(max(frame.width * 0.4, 60.0))
            val bar = barMetres * frame.pixelsPerMetre
            appendLine("""<g id="scale-bar"><line x1="${fmt(MARGIN)}" y1="${fmt(height - 15)}" x2="${fmt(MARGIN + bar)}" y2="${fmt(height - 15)}" stroke="black" stroke-width="2"/>""")
            appendLine("""<text x="${fmt(MARGIN + bar + 6)}" y="${fmt(height - 11)}" font-family="sans-serif" font-size="12">${distance(barMetres)}</text></g>""")
            appendLine("</svg>")
        }
    }

    /** Maps a location to canvas pixels. */
    private fun interface Projection {
        fun pixel(l: Location): Pair<Double, Double>

        fun points(list: List<Location>): String = list.joinToString(" ") { l -> pixel(l).let { (x, y) -> "${fmt(x)},${fmt(y)}" } }
    }

    /** Fence zones under everything else: inclusion outlined in green, exclusion filled in red. */
    private fun StringBuilder.zoneLayers(px: Projection, pixelsPerMetre: Double) {
        if (zones.isEmpty()) return
        appendLine("""<g id="fence">""")
        for (z in zones) {
            val kind = if (z.inclusion) "inclusion" else "exclusion"
            val style = if (z.inclusion) """fill="$INCLUSION" fill-opacity="0.06" stroke="$INCLUSION" stroke-width="2" stroke-dasharray="8 4"""" else """fill="$EXCLUSION" fill-opacity="0.18" stroke="$EXCLUSION" stroke-width="1.5""""
            val title = "<title>${escape(z.label)} ($kind)</title>"
            val centre = z.centre
            if (centre != null) {
                val (x, y) = px.pixel(centre)
                appendLine("""<circle class="fence-$kind" cx="${fmt(x)}" cy="${fmt(y)}" r="${fmt(z.radius * pixelsPerMetre)}" $style>$title</circle>""")
            } else {
                appendLine("""<polygon class="fence-$kind" points="${px.points(z.vertices)}" $style>$title</polygon>""")
            }
        }
        appendLine("</g>")
    }

    private fun StringBuilder.vehicleLayers(px: Projection) {
        if (plans.isNotEmpty()) {
            appendLine("""<g id="plan-mission">""")
            plans.forEachIndexed { n, (label, points) ->
                appendLine("""<polyline class="plan-path" fill="none" stroke="$PATH" stroke-width="1.5" stroke-dasharray="6 4" points="${px.points(points)}"><title>${escape(label)}</title></polyline>""")
                val numbers = planNumbers.getValue(n)
                points.forEachIndexed { i, p -> px.pixel(p).let { (x, y) ->
                    appendLine("""<circle class="plan-item" cx="${fmt(x)}" cy="${fmt(y)}" r="2.5" fill="$PATH"/>""")
                    appendLine("""<text class="item-number" x="${fmt(x + 5)}" y="${fmt(y - 5)}" font-family="sans-serif" font-size="10" fill="$PATH">${escape(numbers[i])}</text>""")
                } }
            }
            appendLine("</g>")
        }
        for ((planned, group) in listOf(true to "planned", false to "flown")) {
            val layer = lines.filter { it.planned == planned }
            if (layer.isEmpty()) continue
            appendLine("""<g id="$group">""")
            for (line in layer) {
                val style = if (planned) """stroke-width="1.5" stroke-dasharray="6 4" stroke-opacity="0.6"""" else """stroke-width="2.5""""
                val colour = colour(line.vehicleId)
                appendLine("""<polyline class="vehicle-${line.vehicleId}" fill="none" stroke="$colour" $style points="${px.points(line.points)}"><title>${escape(line.label)}</title></polyline>""")
                if (planned) line.points.forEachIndexed { i, p -> px.pixel(p).let { (x, y) ->
                    appendLine("""<circle cx="${fmt(x)}" cy="${fmt(y)}" r="2.5" fill="$colour"/>""")
                    appendLine("""<text class="item-number vehicle-${line.vehicleId}" x="${fmt(x + 5)}" y="${fmt(y - 5)}" font-family="sans-serif" font-size="10" fill="$colour">${i + 1}</text>""")
                } }
            }
            // Each flown track's vehicle named where its track ends; tracks ending together (at a
            // shared home) get their names one under the other, not on top of each other.
            val taken = mutableListOf<Pair<Double, Double>>()
            if (!planned) layer.associateBy { it.vehicleId }.forEach { (id, line) -> px.pixel(line.points.last()).let { (x, end) ->
                var y = end
                while (taken.any { (tx, ty) -> kotlin.math.abs(tx - x) < LABEL_WIDTH && kotlin.math.abs(ty - y) < LABEL_HEIGHT }) y += LABEL_HEIGHT
                taken += x to y
                appendLine("""<text class="vehicle-label vehicle-$id" x="${fmt(x + 6)}" y="${fmt(y - 6)}" font-family="sans-serif" font-size="11" fill="${colour(id)}">${escape(line.label)}</text>""")
            } }
            appendLine("</g>")
        }
    }

    private fun StringBuilder.forwardLayers(px: Projection) {
        if (forward.isNotEmpty()) {
            appendLine("""<g id="forward-path">""")
            for ((photographed, run) in surveyLegs(forward)) {
                val style = if (photographed) """class="track-leg" stroke-width="1.5"""" else """class="turn-leg" stroke-width="1.2" stroke-dasharray="2 3""""
                appendLine("""<polyline $style fill="none" stroke="$PATH" points="${px.points(run)}"/>""")
            }
            appendLine("</g>")
            appendLine("""<g id="photo-waypoints">""")
            forward.forEachIndexed { i, wp ->
                if (wp.photo) px.pixel(wp.location).let { (x, y) -> appendLine("""<circle class="photo" data-waypoint="$i" cx="${fmt(x)}" cy="${fmt(y)}" r="2.5" fill="$PATH"/>""") }
            }
            appendLine("</g>")
        }
    }

    /** Each home as a small square in its vehicle's colour. */
    private fun StringBuilder.labelLayers(px: Projection) {
        if (homes.isNotEmpty()) {
            appendLine("""<g id="homes">""")
            homes.forEach { (id, at) -> px.pixel(at).let { (x, y) ->
                appendLine("""<rect class="home vehicle-$id" x="${fmt(x - 4)}" y="${fmt(y - 4)}" width="8" height="8" fill="white" stroke="${colour(id)}" stroke-width="2"><title>${if (id == 0) "planned home" else "home of " + escape(vehicleNames[id] ?: "vehicle $id")}</title></rect>""")
            } }
            appendLine("</g>")
        }
    }

    private fun StringBuilder.markerLayers(px: Projection) {
        if (rally.isNotEmpty()) {
            appendLine("""<g id="rally">""")
            rally.forEachIndexed { i, r -> px.pixel(r).let { (x, y) ->
                appendLine("""<g class="rally-point"><title>rally point ${i + 1}</title><circle cx="${fmt(x)}" cy="${fmt(y)}" r="7" fill="$RALLY"/>""" +
                    """<text x="${fmt(x)}" y="${fmt(y + 4)}" text-anchor="middle" font-family="sans-serif" font-size="10" font-weight="bold" fill="white">R</text></g>""")
            } }
            appendLine("</g>")
        }
        if (objects.isNotEmpty()) {
            appendLine("""<g id="objects">""")
            objects.forEach { o -> px.pixel(o).let { (x, y) -> appendLine(cross(x, y, OBJECT, """ class="object"""")) } }
            appendLine("</g>")
        }
        if (detections.isNotEmpty()) {
            appendLine("""<g id="detections">""")
            // Named as the map numbers them: the backward stop's number (1, 2, …) where it is one.
            val stops = backward.mapIndexed { n, (i, _) -> i to n + 1 }.toMap()
            for ((i, l) in detections) px.pixel(l).let { (x, y) ->
                val name = stops[i]?.let { "backward stop $it (forward waypoint ${i + 1})" } ?: "forward waypoint ${i + 1}"
                appendLine("""<circle class="detection" data-waypoint="$i" cx="${fmt(x)}" cy="${fmt(y)}" r="6" fill="none" stroke="$DETECTION" stroke-width="2.5"><title>$name detected something</title></circle>""")
            }
            appendLine("</g>")
        }
        if (backward.isNotEmpty()) {
            appendLine("""<g id="backward-path">""")
            appendLine("""<polyline class="backward-leg" fill="none" stroke="$BACKWARD" stroke-width="2.5" points="${px.points(backward.map { it.second })}"/>""")
            backward.forEachIndexed { n, (i, l) ->
                val (x, y) = px.pixel(l)
                appendLine("""<circle class="backward-stop" data-waypoint="$i" cx="${fmt(x)}" cy="${fmt(y)}" r="4" fill="$BACKWARD"/>""")
                appendLine("""<text class="backward-number" data-waypoint="$i" x="${fmt(x + 7)}" y="${fmt(y - 7)}" font-family="sans-serif" font-size="12" fill="$BACKWARD">${n + 1}</text>""")
            }
            appendLine("</g>")
        }
    }

    private fun legendEntries(): List<LegendEntry> = buildList {
        if (area.isNotEmpty()) add(LegendEntry("survey-area", Swatch.AREA, AREA, "survey area"))
        if (forward.isNotEmpty()) {
            add(LegendEntry("forward-path", Swatch.SOLID, PATH, "forward path (tracks)"))
            if (surveyLegs(forward).any { !it.first }) add(LegendEntry("forward-path", Swatch.DOTTED, PATH, "turnaround / transit legs"))
            if (forward.any { it.photo }) add(LegendEntry("photo-waypoints", Swatch.DOT, PATH, "photo waypoint"))
        }
        if (zones.any { it.inclusion }) add(LegendEntry("fence", Swatch.FENCE_IN, INCLUSION, "fence: stay inside"))
        if (zones.any { !it.inclusion }) add(LegendEntry("fence", Swatch.FENCE_OUT, EXCLUSION, "fence: keep out"))
        if (plans.isNotEmpty()) add(LegendEntry("plan-mission", Swatch.DASHED, PATH, "planned mission"))
        if (lines.any { it.planned }) add(LegendEntry("planned", Swatch.DASHED, NEUTRAL, "planned mission (dashed)"))
        if (lines.any { !it.planned }) add(LegendEntry("flown", Swatch.SOLID, NEUTRAL, "flown track (solid)"))
        // A vehicle known by its home alone (a log with no track) is named in the legend too.
        for (id in (lines.map { it.vehicleId } + homes.keys.filter { it != 0 }).distinct().sorted()) {
            add(LegendEntry("vehicle-$id", Swatch.SOLID, colour(id), vehicleNames[id] ?: "vehicle $id"))
        }
        if (homes.isNotEmpty()) add(LegendEntry("homes", Swatch.SQUARE, NEUTRAL, "home"))
        if (rally.isNotEmpty()) add(LegendEntry("rally", Swatch.RALLY, RALLY, "rally point"))
        if (objects.isNotEmpty()) add(LegendEntry("objects", Swatch.CROSS, OBJECT, "object on the ground"))
        if (detections.isNotEmpty()) add(LegendEntry("detections", Swatch.RING, DETECTION, "waypoint that detected"))
        if (backward.isNotEmpty()) add(LegendEntry("backward-path", Swatch.NUMBERED, BACKWARD, "backward path, in order"))
    }

    private companion object {
        const val MARGIN = 30.0
        const val TOP = 44.0
        const val BOTTOM = 40.0
        const val MIN_WIDTH = 360.0

        /** A vehicle label's room: labels closer than this across and down are stacked. */
        const val LABEL_WIDTH = 60.0
        const val LABEL_HEIGHT = 13.0

        val PALETTE = listOf("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2")

        // Survey colours stay clear of the vehicle palette, so a layer never reads as a vehicle.
        const val AREA = "#4a90a4"
        const val PATH = "#555555"
        const val OBJECT = "#111111"
        const val DETECTION = "#e6ab02"
        const val BACKWARD = "#c51b8a"
        const val NEUTRAL = "#777777"
        const val INCLUSION = "#1a9850"
        const val EXCLUSION = "#d73027"
        const val RALLY = "#ff7f00"

        /** A vehicle's colour; id 0 (a plan's planned home, no vehicle's) is neutral. */
        fun colour(vehicleId: Int) = if (vehicleId == 0) NEUTRAL else PALETTE[(vehicleId - 1).mod(PALETTE.size)]

        fun distance(metres: Double): String = when {
            metres >= 1000 -> "${trim(metres / 1000)} km"
            else -> "${trim(metres)} m"
        }

        private fun trim(d: Double) = if (d == Math.rint(d)) d.toLong().toString() else d.toString()
    }
}
