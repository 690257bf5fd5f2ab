package pod.launch.map

import pod.core.units.Location
import java.util.Locale
import kotlin.math.floor
import kotlin.math.log10
import kotlin.math.max
import kotlin.math.pow

/**
 * Where a map's points go on the canvas: everything projected flat around the first point (core's
 * flat Earth, exact enough over the few kilometres a survey or a demo flies), scaled to fit a box
 * of at most [maxWidth] × [maxHeight] pixels, north up. The canvas is then cut to the content, so a tall
 * narrow survey gets a tall narrow picture instead of one lost in blank space.
 */
internal class MapFrame(points: List<Location>, maxWidth: Double, maxHeight: Double) {
    private val origin = points.firstOrNull() ?: Location(0.0, 0.0)
    private val minX: Double
    private val minY: Double
    private val scale: Double

    /** Pixels per metre. */
    val pixelsPerMetre: Double get() = scale

    /** Width of the drawn map area, in pixels. */
    val width: Double

    /** Height of the drawn map area, in pixels. */
    val height: Double

    init {
        val xy = points.map(::metres)
        minX = xy.minOfOrNull { it.first } ?: 0.0
        minY = xy.minOfOrNull { it.second } ?: 0.0
        // A single point (or a straight north-south line) has no extent on one axis: give it a
        // metre, so the scale stays finite.
        val spanX = max((xy.maxOfOrNull { it.first } ?: 0.0) - minX, 1.0)
        val spanY = max((xy.maxOfOrNull { it.second } ?: 0.0) - minY, 1.0)
        scale = minOf(maxWidth / spanX, maxHeight / spanY)
        width = spanX * scale
        height = spanY * scale
    }

    /** [p] in map-area pixels: x from the left edge, y down from the top edge. */
    fun pixel(p: Location): Pair<Double, Double> {
        val (x, y) = metres(p)
        return (x - minX) * scale to height - (y - minY) * scale
    }

    /** [p] as metres east (x) and north (y) of the origin, on core's flat Earth ([Location.northEastTo]). */
    private fun metres(p: Location): Pair<Double, Double> =
        origin.northEastTo(p).let { (north, east) -> east.meters to north.meters }

    /**
     * The scale bar's length in metres: the longest 1, 2 or 5 × 10ⁿ m that is at most [maxPixels]
     * long (a fixed 100 m bar would run off the canvas of a small survey).
     */
    fun scaleBarMetres(maxPixels: Double): Double {
        val limit = maxPixels / scale
        val decade = 10.0.pow(floor(log10(limit)))
        return listOf(5.0, 2.0, 1.0).map { it * decade }.first { it <= limit }
    }

    companion object {
        /** [d] with one decimal and a point, whatever the default locale (SVG needs the point). */
        fun fmt(d: Double): String = String.format(Locale.ROOT, "%.1f", d)
    }
}
