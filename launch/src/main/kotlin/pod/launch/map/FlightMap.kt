package pod.launch.map

import pod.core.PodException
import pod.launch.geo.GeoFeature
import pod.launch.geo.GeoJson
import pod.launch.geo.GeoShape
import pod.launch.geo.Kml
import pod.launch.geo.MapFeatures
import pod.mavlink.plan.QgcPlan
import pod.mavlink.tlog.FlownTrack
import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path

/**
 * One map of plans and flights, written as SVG, GeoJSON or KML from the same [features].
 *
 * ```
 * val map = FlightMap("Field 7")
 * map.plan(QgcPlanFile.read(Path.of("field7.plan")))
 * TlogTracks.read(Path.of("flight.tlog")).tracks.forEach(map::track)
 * map.write(Path.of("field7.svg"))   // or .geojson / .kml
 * ```
 *
 * The SVG draws each feature by its `kind` (see [MapFeatures]); features of other kinds (from a
 * GeoJSON file made elsewhere) are drawn as plain mission-style lines, areas and points.
 */
public class FlightMap(
    /** The map's title (SVG heading, KML document name). */
    public val title: String,
) {
    private val added = mutableListOf<GeoFeature>()

    /** Everything on the map so far, in the order added. */
    public val features: List<GeoFeature> get() = added.toList()

    /** Adds [features]. */
    public fun add(features: List<GeoFeature>): FlightMap = apply { added += features }

    /** Adds [plan]'s mission (called [name]), fence zones, rally points and planned home. */
    public fun plan(plan: QgcPlan, name: String = "mission"): FlightMap = add(MapFeatures.of(plan, name))

    /** Adds where a vehicle flew and its home. */
    public fun track(track: FlownTrack): FlightMap = add(MapFeatures.of(track))

    /** The map as an SVG document. */
    public fun svg(): String {
        val map = SvgMap()
        for (f in added) {
            val kind = f.properties["kind"]
            val vehicle = (f.properties["vehicle"] as? Number)?.toInt()
            val label = f.name ?: kind?.toString() ?: "feature"
            when (val s = f.shape) {
                is GeoShape.Line -> when {
                    kind == MapFeatures.TRACK && vehicle != null -> map.flown(vehicle, label, s.points)
                    vehicle != null -> map.planned(vehicle, label, s.points)
                    else -> map.plannedPath(label, s.points, (f.properties[MapFeatures.NUMBERS] as? String)?.split(","))
                }
                is GeoShape.Polygon -> map.fence(s.vertices, inclusion = f.properties["inclusion"] != false, label)
                is GeoShape.Point -> {
                    val radius = (f.properties["radius"] as? Number)?.toDouble()
                    when {
                        radius != null && radius > 0 -> map.fenceCircle(s.at, radius, inclusion = f.properties["inclusion"] != false, label)
                        kind == MapFeatures.HOME -> map.home(vehicle ?: 0, s.at)
                        else -> map.rallyPoint(s.at)
                    }
                }
            }
        }
        return map.render(title)
    }

    /** The map as a GeoJSON FeatureCollection. */
    public fun geoJson(): String = GeoJson.write(added)

    /** The map as a KML document. */
    public fun kml(): String = Kml.write(added, title)

    /**
     * Writes the map to [path] in the format its extension names (`.svg`, `.geojson` or `.json`,
     * `.kml`); throws [MapFormatUnknown] for another extension and [MapWriteFailed] when the file
     * cannot be written.
     */
    public fun write(path: Path) {
        val text = when (MapFormat.of(path)) {
            MapFormat.SVG -> svg()
            MapFormat.GEOJSON -> geoJson()
            MapFormat.KML -> kml()
        }
        try {
            path.toAbsolutePath().parent?.let { Files.createDirectories(it) }
            Files.writeString(path, text)
        } catch (e: IOException) {
            throw MapWriteFailed(path, e)
        }
    }
}

/** The file formats a [FlightMap] writes. */
public enum class MapFormat(
    /** File name extensions, lower case, without the dot. */
    public val extensions: List<String>,
) {
    /** An SVG picture. */
    SVG(listOf("svg")),

    /** A GeoJSON FeatureCollection (RFC 7946). */
    GEOJSON(listOf("geojson", "json")),

    /** KML 2.2, as Google Earth reads it. */
    KML(listOf("kml")),
    ;

    /** Finds the format a file name asks for. */
    public companion object {
        /** The format [path]'s extension names; throws [MapFormatUnknown] otherwise. */
        public fun of(path: Path): MapFormat {
            val extension = path.fileName?.toString()?.substringAfterLast('.', "")?.lowercase().orEmpty()
            return entries.firstOrNull { extension in it.extensions } ?: throw MapFormatUnknown(path)
        }
    }
}

/** A map file name whose extension is not one of [MapFormat]'s. */
public class MapFormatUnknown(
    /** The file asked for. */
    public val path: Path,
) : PodException("cannot tell the map format of $path: name it .svg, .geojson or .kml")

/** A map that could not be written to [path]. */
public class MapWriteFailed(
    /** The file that could not be written. */
    public val path: Path,
    cause: IOException,
) : PodException("cannot write the map to $path: ${cause.message}", cause)
