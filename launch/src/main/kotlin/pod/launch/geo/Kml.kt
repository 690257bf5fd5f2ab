package pod.launch.geo

import pod.core.units.Location
import java.util.Locale

/**
 * KML 2.2 for [GeoFeature]s, as Google Earth and GIS tools read it: one Placemark per feature
 * (Point, LineString, Polygon with its ring closed), coordinates `longitude,latitude,altitude` with
 * the altitude absolute (above mean sea level), the `name` property as the Placemark's name and the
 * others as ExtendedData.
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
            when (val s = f.shape) {
                is GeoShape.Point -> appendLine("    <Point><altitudeMode>absolute</altitudeMode><coordinates>${coordinate(s.at)}</coordinates></Point>")
                is GeoShape.Line -> appendLine("    <LineString><altitudeMode>absolute</altitudeMode><coordinates>${s.points.joinToString(" ", transform = ::coordinate)}</coordinates></LineString>")
                is GeoShape.Polygon -> appendLine(
                    "    <Polygon><altitudeMode>absolute</altitudeMode><outerBoundaryIs><LinearRing><coordinates>" +
                        (s.vertices + s.vertices.first()).joinToString(" ", transform = ::coordinate) +
                        "</coordinates></LinearRing></outerBoundaryIs></Polygon>",
                )
            }
            appendLine("  </Placemark>")
        }
        appendLine("</Document>")
        appendLine("</kml>")
    }

    // Locale.ROOT: a decimal comma would split a coordinate in two.
    private fun coordinate(l: Location) = String.format(Locale.ROOT, "%.8f,%.8f,%.2f", l.longitude, l.latitude, l.altitude.meters)

    private fun escape(text: String) = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;")
}
