package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.options.required
import pod.launch.geo.MapFeatures
import pod.launch.map.FlightMap
import pod.mavlink.mission.MissionType
import java.nio.file.Path

/**
 * `pod map INPUT… --out FILE`: draws plans, missions and flown tracks on one map, as SVG, GeoJSON
 * or KML by the output's extension. Inputs by theirs: `.plan` (mission, fence, rally, home),
 * `.tlog` (every vehicle's track and home), `.waypoints`/`.txt` (QGC WPL mission), `.geojson`/
 * `.json` (features, drawn by their `kind`).
 */
internal class MapCommand(private val out: Output) : CliktCommand(name = "map") {
    private val inputs by argument("INPUT", help = ".plan, .tlog, .waypoints or .geojson files").multiple(required = true)
    private val output by option("--out", help = "the map to write: .svg, .geojson or .kml").required()
    private val title by option("--title", help = "the map's title (default: the input file names)")

    override fun help(context: Context): String = "Draw plans and flown tracks on a map (SVG, GeoJSON or KML)."

    override fun run() {
        LocalFiles.checkMapOutput(output)
        val map = FlightMap(title ?: inputs.joinToString(" + ") { Path.of(it).fileName.toString() })
        val counts = sortedMapOf<String, Int>()
        for (name in inputs) {
            val added = when (name.substringAfterLast('.', "").lowercase()) {
                "plan" -> {
                    val plan = LocalFiles.readPlan(name)
                    plan.warnings.forEach { out.line("warning: $name: $it") }
                    MapFeatures.of(plan, Path.of(name).fileName.toString())
                }
                "tlog" -> {
                    val flight = LocalFiles.readTracks(name)
                    // Not one whole record: not a tlog at all, rather than one cut short.
                    if (flight.records == 0L && flight.error != null) badInput("$name is not a tlog: ${flight.error!!.message}")
                    // As pod replay: a log without a single record is bad input (exit 2), not an empty map.
                    if (flight.records == 0L) badInput("$name is empty: no tlog record to map")
                    flight.error?.let { out.line("warning: $name: ${it.message}; mapped the ${flight.records} records before it") }
                    if (flight.tracks.isEmpty()) out.line("warning: $name: no vehicle heartbeat in ${flight.records} records")
                    flight.tracks.flatMap(MapFeatures::of)
                }
                "waypoints", "txt" -> MapFeatures.mission(LocalFiles.readWpl(name, MissionType.MISSION), Path.of(name).fileName.toString())
                "geojson", "json" -> LocalFiles.readGeoJson(name)
                else -> badInput("cannot tell what $name holds: give a .plan, .tlog, .waypoints or .geojson file")
            }
            added.forEach { f -> counts.merge(f.properties["kind"]?.toString() ?: "other", 1, Int::plus) }
            map.add(added)
        }
        LocalFiles.writeMap(map, output)
        val summary = if (counts.isEmpty()) "nothing to draw" else counts.entries.joinToString(", ") { (kind, n) -> "$n $kind" }
        out.line("wrote $output: $summary")
    }
}
