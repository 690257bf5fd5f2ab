package pod.e2e

import io.kotest.core.spec.style.StringSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.launch
import org.w3c.dom.Element
import pod.core.platform.PlatformVehicle
import pod.core.units.Location
import pod.core.units.m
import pod.dsl.concurrently
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.launch.geo.GeoJson
import pod.launch.geo.GeoShape
import pod.launch.geo.MapFeatures
import pod.mavlink.tlog.TlogTracks
import pod.mavlink.tlog.TlogWriter
import pod.sim.SimFlavor
import java.io.File
import javax.xml.parsers.DocumentBuilderFactory
import kotlin.math.cos
import kotlin.math.hypot
import kotlin.time.Duration.Companion.seconds

/** A square: take off, 40 m out one way, 40 m the other, back home and land. */
private fun square(v: PlatformVehicle, northFirst: Boolean) = mission("square ${v.name}") {
    home(v.home.value!!)
    takeOff(15.m)
    if (northFirst) move(north = 40.m) else move(east = 40.m)
    if (northFirst) move(east = 40.m) else move(north = 40.m)
    returnHomeAndLand()
}

/** Metres from [p] to the segment [a]–[b], in a local flat frame (fine over a few hundred metres). */
private fun distanceToSegment(p: Location, a: Location, b: Location): Double {
    val k = cos(Math.toRadians(a.latitude))
    fun xy(l: Location) = ((l.longitude - a.longitude) * k * 111_320.0) to ((l.latitude - a.latitude) * 110_574.0)
    val (px, py) = xy(p)
    val (bx, by) = xy(b)
    val length2 = bx * bx + by * by
    val t = if (length2 == 0.0) 0.0 else ((px * bx + py * by) / length2).coerceIn(0.0, 1.0)
    return hypot(px - t * bx, py - t * by)
}

private fun distanceToPath(p: Location, path: List<Location>) = path.zipWithNext().minOf { (a, b) -> distanceToSegment(p, a, b) }

/**
 * The acceptance for maps of flights: what a station recorded to a tlog, drawn with
 * `pod map`, is the track that station saw live.
 */
class FlightMapSpec : StringSpec({
    "a flight recorded to a tlog, mapped with pod map or replayed with pod replay --map, shows each vehicle's live track and home" {
        val dir = tempdir()
        val tlog = File(dir, "flight.tlog")
        val live = HashMap<Int, MutableList<Location>>()
        val homes = HashMap<Int, Location>()
        virtualRun {
            simulate(listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4)) { sim ->
                val writer = TlogWriter.create(tlog.toPath())
                val recording = sim.station.record(writer, startEpochMicros = 1_700_000_000_000_000L)
                val (a, b) = pick { count(2) }.toList()
                coroutineScope {
                    val watching = listOf(a, b).map { v ->
                        val seen = mutableListOf<Location>().also { live[v.id] = it }
                        // The first value is what the station held before recording began: not in the log.
                        var first = true
                        launch { sim.platform.mavlink(v).telemetry.position.filterNotNull().collect { if (first) first = false else seen += it.location } }
                    }
                    execute(concurrently(square(a, northFirst = true) on a, square(b, northFirst = false) on b))
                    watching.forEach { it.cancel() }
                }
                recording.stop()
                writer.close()
                listOf(a, b).forEach { homes[it.id] = it.home.value!! }
            }
        }

        // Every position the station saw live is in the log, in order, exactly.
        val logged = TlogTracks.read(tlog.toPath(), stepMetres = 0.0)
        logged.error shouldBe null
        logged.tracks.map { it.systemId }.sorted() shouldBe live.keys.sorted()
        for (track in logged.tracks) {
            val seen = live.getValue(track.systemId)
            (seen.size > 100) shouldBe true
            var at = 0
            for (p in seen) {
                while (at < track.points.size && track.points[at] != p) at++
                (at < track.points.size) shouldBe true
            }
        }

        val geojson = File(dir, "flight.geojson").path
        val mapped = pod("map", tlog.path, "--out", geojson)
        mapped.code shouldBe 0
        mapped.out shouldBe listOf("wrote $geojson: 2 home, 2 track")
        val features = GeoJson.read(File(geojson).readText())
        for ((id, seen) in live) {
            val track = features.single { it.properties["kind"] == MapFeatures.TRACK && it.properties["vehicle"] == id.toLong() }
            val points = (track.shape as GeoShape.Line).points
            // Thinned to a point a metre, the mapped track still passes within a metre of every
            // live position, and ends where the vehicle was last seen.
            points.last() shouldBe seen.last()
            seen.maxOf { distanceToPath(it, points) } shouldBeLessThan 1.0
            // The squares really were flown.
            val farthest = seen.maxOf { it.copy(altitude = homes.getValue(id).altitude).distanceTo(homes.getValue(id)).meters }
            // The far corner is 56.6 m out; PX4 turns up to its acceptance radius (10 m) early.
            farthest shouldBe (52.0 plusOrMinus 6.0)
            val home = features.single { it.properties["kind"] == MapFeatures.HOME && it.properties["vehicle"] == id.toLong() }
            (home.shape as GeoShape.Point).at.distanceTo(homes.getValue(id)).meters shouldBeLessThan 0.01
        }

        // Played back with pod replay, the same log draws the same tracks and homes: every frame
        // reached the replaying station, in order (a dropped or reordered position would move a
        // thinned point), and its tracks pass within a metre of every live position.
        val replayed = File(dir, "replay.geojson").path
        val replay = pod("replay", tlog.path, "--speed", "1000", "--map", replayed, within = 60.seconds)
        replay.code shouldBe 0
        replay.out.last() shouldStartWith "replayed ${logged.records} records"
        replay.out.filter { it.startsWith("found vehicle") }.size shouldBe 2
        val replayFeatures = GeoJson.read(File(replayed).readText())
        replayFeatures shouldBe features
        for ((id, seen) in live) {
            val track = replayFeatures.single { it.properties["kind"] == MapFeatures.TRACK && it.properties["vehicle"] == id.toLong() }
            seen.maxOf { distanceToPath(it, (track.shape as GeoShape.Line).points) } shouldBeLessThan 1.0
        }

        val svg = File(dir, "flight.svg").path
        pod("map", tlog.path, "--out", svg).code shouldBe 0
        val doc = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(File(svg)).documentElement
        val groups = doc.getElementsByTagName("g").let { g -> (0 until g.length).map { g.item(it) as Element } }
        val flown = groups.single { it.getAttribute("id") == "flown" }.getElementsByTagName("polyline")
        (0 until flown.length).map { (flown.item(it) as Element).getAttribute("class") }.sorted() shouldBe live.keys.sorted().map { "vehicle-$it" }
        groups.single { it.getAttribute("id") == "homes" }.getElementsByTagName("rect").length shouldBe 2
    }
})
