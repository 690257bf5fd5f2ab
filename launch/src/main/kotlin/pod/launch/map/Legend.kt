package pod.launch.map

import pod.launch.map.MapFrame.Companion.fmt

/** How a legend entry's sample is drawn: the same marker or stroke as the layer it names. */
internal enum class Swatch { AREA, SOLID, DASHED, DOTTED, DOT, RING, CROSS, NUMBERED, SQUARE, FENCE_IN, FENCE_OUT, RALLY }

/** One line of the legend: a sample in [colour] and [label]; [layer] is the id of the layer it names. */
internal data class LegendEntry(val layer: String, val swatch: Swatch, val colour: String, val label: String)

/** Draws legend entries as a column, one [ROW] pixels high each, starting at ([x], [y]). */
internal object Legend {
    const val ROW = 20.0
    const val WIDTH = 230.0

    /** Labels longer than this are cut (the full text stays in the entry's tooltip). */
    private const val MAX_LABEL = 28

    fun height(entries: List<LegendEntry>): Double = if (entries.isEmpty()) 0.0 else ROW * (entries.size + 1)

    fun render(out: StringBuilder, entries: List<LegendEntry>, x: Double, y: Double) {
        if (entries.isEmpty()) return
        out.appendLine("""<g id="legend">""")
        out.appendLine("""<text x="${fmt(x)}" y="${fmt(y + 12)}" font-family="sans-serif" font-size="13" font-weight="bold">Legend</text>""")
        entries.forEachIndexed { i, e ->
            val top = y + ROW * (i + 1)
            val mid = top + ROW / 2
            val label = if (e.label.length > MAX_LABEL) e.label.take(MAX_LABEL - 1) + "…" else e.label
            out.appendLine("""<g class="legend-entry" data-layer="${e.layer}"><title>${escape(e.label)}</title>""")
            out.appendLine(swatch(e.swatch, e.colour, x, mid))
            out.appendLine("""<text x="${fmt(x + 30)}" y="${fmt(mid + 4)}" font-family="sans-serif" font-size="12">${escape(label)}</text></g>""")
        }
        out.appendLine("</g>")
    }

    private fun swatch(kind: Swatch, colour: String, x: Double, y: Double): String {
        fun line(extra: String, w: Double = 2.5) =
            """<line x1="${fmt(x)}" y1="${fmt(y)}" x2="${fmt(x + 22)}" y2="${fmt(y)}" stroke="$colour" stroke-width="$w"$extra/>"""
        val cx = fmt(x + 11)
        val cy = fmt(y)
        return when (kind) {
            Swatch.AREA -> """<rect x="${fmt(x)}" y="${fmt(y - 6)}" width="22" height="12" fill="$colour" fill-opacity="0.2" stroke="$colour"/>"""
            Swatch.SOLID -> line("")
            Swatch.DASHED -> line(""" stroke-dasharray="6 4"""", 1.5)
            Swatch.DOTTED -> line(""" stroke-dasharray="2 3"""", 1.5)
            Swatch.DOT -> """<circle cx="$cx" cy="$cy" r="2.5" fill="$colour"/>"""
            Swatch.RING -> """<circle cx="$cx" cy="$cy" r="6" fill="none" stroke="$colour" stroke-width="2.5"/>"""
            Swatch.CROSS -> cross(x + 11, y, colour, "")
            Swatch.SQUARE -> """<rect x="${fmt(x + 7)}" y="${fmt(y - 4)}" width="8" height="8" fill="white" stroke="$colour" stroke-width="2"/>"""
            Swatch.FENCE_IN -> """<rect x="${fmt(x)}" y="${fmt(y - 6)}" width="22" height="12" fill="$colour" fill-opacity="0.06" stroke="$colour" stroke-width="2" stroke-dasharray="8 4"/>"""
            Swatch.FENCE_OUT -> """<rect x="${fmt(x)}" y="${fmt(y - 6)}" width="22" height="12" fill="$colour" fill-opacity="0.18" stroke="$colour" stroke-width="1.5"/>"""
            Swatch.RALLY -> """<circle cx="$cx" cy="$cy" r="7" fill="$colour"/><text x="$cx" y="${fmt(y + 4)}" text-anchor="middle" font-family="sans-serif" font-size="10" font-weight="bold" fill="white">R</text>"""
            Swatch.NUMBERED -> line("") +
                """<circle cx="$cx" cy="$cy" r="4" fill="$colour"/>"""
        }
    }
}

/** An × of half-size 4 px centred on ([x], [y]), as one path element. */
internal fun cross(x: Double, y: Double, colour: String, attributes: String): String =
    """<path$attributes d="M${fmt(x - 4)},${fmt(y - 4)} L${fmt(x + 4)},${fmt(y + 4)} M${fmt(x - 4)},${fmt(y + 4)} L${fmt(x + 4)},${fmt(y - 4)}" stroke="$colour" stroke-width="2" fill="none"/>"""

/** [text] made safe for SVG text and attribute values. */
internal fun escape(text: String): String =
    text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;")
