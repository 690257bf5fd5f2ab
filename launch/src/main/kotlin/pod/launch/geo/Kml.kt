package pod.launch.geo

import pod.core.units.Location
import pod.core.units.m
import java.util.Locale
import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.sin

/**
 * KML 2.2 for [GeoFeature]s, as Google Earth and GIS tools read it: one Placemark per feature
 * (Point, LineString, Polygon with its ring closed), coordinates `longitude,latitude,altitude` with
 * the altitude absolute (above mean sea level), the `name` property as the Placemark's name and the
 * others as ExtendedData. A Point with a `radius` property (a circular fence, see [MapFeatures]) is
 * written as that circle, a ring of [CIRCLE_VERTICES] vertices, since KML has no circles.
 */
public object Kml {
    /** [features] as a KML document called [name]. */
    public fun write(features: List<GeoFeature>, name: String): String = buildString {
        appendLine("""<?xml version="1.0" encoding="UTF-8"?>""")
        appendLine("""<kml xmlns="http://www.opengis.net/kml/2.2">""")
        appendLine("<Document>")
        appendLine("  <name>${escape(name)}</name>")
        for (f in features) {
            appendLine("  <Placemark>")
            f.name?.let { appendLine("    <name>${escape(it)}</name>") }
            val data = f.properties.filterKeys { it != "name" }
            if (data.isNotEmpty()) {
                appendLine("    <ExtendedData>")
                data.forEach { (key, value) -> appendLine("""      <Data name="${escape(key)}"><value>${escape(value.toString())}</value></Data>""") }
                appendLine("    </ExtendedData>")
            }
            val radius = (f.properties["radius"] as? Number)?.toDouble()?.takeIf { it > 0 }
            when (val s = f.shape) {
                is GeoShape.Point -> if (radius != null) {
                    appendLine(polygon((0 until CIRCLE_VERTICES).map { i ->
                        val a = 2 * PI * i / CIRCLE_VERTICES
                        s.at.offset((radius * cos(a)).m, (radius * sin(a)).m)
                    }))
                } else {
                    appendLine("    <Point><altitudeMode>absolute</altitudeMode><coordinates>${coordinate(s.at)}</coordinates></Point>")
                }
                is GeoShape.Line -> appendLine("    <LineString><altitudeMode>absolute</altitudeMode><coordinates>${s.points.joinToString(" ", transform = ::coordinate)}</coordinates></LineString>")
                is GeoShape.Polygon -> appendLine(polygon(s.vertices))
            }
            appendLine("  </Placemark>")
        }
        appendLine("</Document>")
        appendLine("</kml>")
    }

    /** How many vertices draw a circle. */
    public const val CIRCLE_VERTICES: Int = 72

    private fun polygon(vertices: List<Location>) =
        "    <Polygon><altitudeMode>absolute</altitudeMode><outerBoundaryIs><LinearRing><coordinates>" +
            (vertices + vertices.first()).joinToString(" ", transform = ::coordinate) +
            "</coordinates></LinearRing></outerBoundaryIs></Polygon>"

    // Locale.ROOT: a decimal comma would split a coordinate in two.
    private fun coordinate(l: Location) = String.format(Locale.ROOT, "%.8f,%.8f,%.2f", l.longitude, l.latitude, l.altitude.meters)

    private fun escape(text: String) = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;")
}
