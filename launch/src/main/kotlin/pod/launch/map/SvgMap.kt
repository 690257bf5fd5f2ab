package pod.launch.map

import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.units.Location
import kotlin.math.cos
import kotlin.math.max

/**
 * Draws planned missions (dashed, with a dot per step) and flown tracks (solid) on one SVG map,
 * north up, with a 100 m scale bar. Coordinates are projected flat around the first point, which
 * is exact enough over the few kilometres a demo flies.
 */
internal class SvgMap(private val width: Int = 900, private val height: Int = 700) {
    private class Line(val label: String, val points: List<Location>, val colour: String, val planned: Boolean)

    private val lines = mutableListOf<Line>()

    /** Adds [mission]'s path as planned for vehicle [vehicleId]. */
    internal fun planned(vehicleId: Int, mission: Mission) {
        val points = mission.steps.filterIsInstance<MissionStep.Navigation>().map { it.location }
        if (points.isNotEmpty()) lines += Line(mission.name, points, colour(vehicleId), planned = true)
    }

    /** Adds a flown track of vehicle [vehicleId]. */
    internal fun flown(vehicleId: Int, name: String, points: List<Location>) {
        if (points.size >= 2) lines += Line(name, points, colour(vehicleId), planned = false)
    }

    /** The SVG document. */
    internal fun render(title: String): String {
        val all = lines.flatMap { it.points }
        val origin = all.firstOrNull() ?: Location(0.0, 0.0)
        val xy = all.map { project(origin, it) }
        val minX = xy.minOfOrNull { it.first } ?: 0.0
        val maxX = xy.maxOfOrNull { it.first } ?: 1.0
        val minY = xy.minOfOrNull { it.second } ?: 0.0
        val maxY = xy.maxOfOrNull { it.second } ?: 1.0
        val margin = 40.0
        val scale = minOf((width - 2 * margin) / max(maxX - minX, 1.0), (height - 2 * margin - 30) / max(maxY - minY, 1.0))
        fun px(l: Location): String {
            val (x, y) = project(origin, l)
            return "%.1f,%.1f".format(margin + (x - minX) * scale, height - margin - (y - minY) * scale)
        }
        return buildString {
            appendLine("""<svg xmlns="http://www.w3.org/2000/svg" width="$width" height="$height" viewBox="0 0 $width $height">""")
            appendLine("""<rect width="100%" height="100%" fill="#fbfbf8"/>""")
            appendLine("""<text x="$margin" y="24" font-family="sans-serif" font-size="16">${escape(title)}</text>""")
            for (line in lines) {
                val dash = if (line.planned) """ stroke-dasharray="6 4" stroke-opacity="0.6"""" else ""
                val widthPx = if (line.planned) 1.5 else 2.5
                appendLine("""<polyline fill="none" stroke="${line.colour}" stroke-width="$widthPx"$dash points="${line.points.joinToString(" ") { px(it) }}"><title>${escape(line.label)}</title></polyline>""")
                if (line.planned) line.points.forEach { p ->
                    val (x, y) = px(p).split(',')
                    appendLine("""<circle cx="$x" cy="$y" r="2.5" fill="${line.colour}"/>""")
                }
            }
            val bar = 100 * scale
            appendLine("""<line x1="$margin" y1="${height - 15}" x2="${margin + bar}" y2="${height - 15}" stroke="black" stroke-width="2"/>""")
            appendLine("""<text x="${margin + bar + 6}" y="${height - 11}" font-family="sans-serif" font-size="12">100 m</text>""")
            appendLine("</svg>")
        }
    }

    private fun project(origin: Location, p: Location): Pair<Double, Double> {
        val metresPerDegree = 111_320.0
        val x = (p.longitude - origin.longitude) * metresPerDegree * cos(Math.toRadians(origin.latitude))
        val y = (p.latitude - origin.latitude) * metresPerDegree
        return x to y
    }

    private fun escape(text: String) = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")

    private companion object {
        val PALETTE = listOf("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2")

        fun colour(vehicleId: Int) = PALETTE[(vehicleId - 1).mod(PALETTE.size)]
    }
}
