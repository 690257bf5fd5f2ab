package pod.launch.map

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.checkAll
import org.w3c.dom.Element
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.VehicleType
import pod.launch.geo.GeoJson
import pod.launch.geo.GeoShape
import pod.launch.geo.MapFeatures
import pod.mavlink.MavFrames
import pod.mavlink.mission.MissionItem
import pod.mavlink.plan.FenceCircle
import pod.mavlink.plan.FencePolygon
import pod.mavlink.plan.PlanGeoFence
import pod.mavlink.plan.PlanPoint
import pod.mavlink.plan.PlanPosition
import pod.mavlink.plan.QgcPlan
import pod.mavlink.tlog.FlownTrack
import java.nio.file.Path
import javax.xml.parsers.DocumentBuilderFactory
import kotlin.math.hypot
import kotlin.math.roundToInt

private val home = Location(47.3977, 8.5456, 488.m)

private fun point(l: Location) = PlanPoint(l.latitude, l.longitude)

private fun square(centre: Location, half: Double) =
    listOf(half to -half, half to half, -half to half, -half to -half).map { (n, e) -> point(centre.offset(n.m, e.m)) }

private fun waypoint(seq: Int, at: Location, relativeAltitude: Float) =
    MissionItem(seq, MavFrames.GLOBAL_RELATIVE_ALT, 16, x = (at.latitude * 1e7).roundToInt(), y = (at.longitude * 1e7).roundToInt(), z = relativeAltitude)

private val plan = QgcPlan(
    mission = listOf(
        MissionItem(0, MavFrames.GLOBAL_RELATIVE_ALT, 22, z = 20f), // take-off here: no position of its own
        waypoint(1, home.offset(100.m, 0.m), 20f),
        waypoint(2, home.offset(100.m, 100.m), 30f),
        waypoint(3, home.offset(0.m, 100.m), 30f),
        MissionItem(4, MavFrames.GLOBAL_RELATIVE_ALT, 20), // RTL
    ),
    geoFence = PlanGeoFence(
        polygons = listOf(FencePolygon(true, square(home.offset(50.m, 50.m), 120.0)), FencePolygon(false, square(home.offset(50.m, 50.m), 10.0).drop(1))),
        circles = listOf(FenceCircle(true, point(home), 300.0), FenceCircle(false, point(home.offset(-60.m, 0.m)), 15.0)),
    ),
    rallyPoints = listOf(PlanPosition(home.offset(0.m, -80.m).latitude, home.offset(0.m, -80.m).longitude, 25.0), PlanPosition(home.offset(-80.m, 0.m).latitude, home.offset(-80.m, 0.m).longitude, 25.0)),
    plannedHome = PlanPosition(home.latitude, home.longitude, 488.0),
)

private fun parse(svg: String): Element = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(svg.byteInputStream()).documentElement

private fun Element.elements(tag: String): List<Element> = getElementsByTagName(tag).let { list -> (0 until list.length).map { list.item(it) as Element } }

private fun Element.group(id: String): Element = elements("g").single { it.getAttribute("id") == id }

class FlightMapTest : FunSpec({
    test("a plan's fence zones, rally points, mission and planned home are drawn in their layers, circles at their radius, the canvas around all of it") {
        val map = FlightMap("field").plan(plan)
        val svg = parse(map.svg())
        val fence = svg.group("fence")
        fence.elements("polygon").map { it.getAttribute("class") } shouldBe listOf("fence-inclusion", "fence-exclusion")
        fence.elements("circle").map { it.getAttribute("class") } shouldBe listOf("fence-inclusion", "fence-exclusion")
        val rally = svg.group("rally").elements("g").filter { it.getAttribute("class") == "rally-point" }
        rally.size shouldBe 2
        // Pixels per metre, from the two rally points (80 m east-west and 80 m north-south of home: 113 m apart).
        val (a, b) = rally.map { it.elements("circle").single().let { c -> c.getAttribute("cx").toDouble() to c.getAttribute("cy").toDouble() } }
        val ppm = hypot(a.first - b.first, a.second - b.second) / home.offset(0.m, -80.m).distanceTo(home.offset(-80.m, 0.m)).meters
        val circles = fence.elements("circle")
        circles[0].getAttribute("r").toDouble() shouldBe (300.0 * ppm plusOrMinus 300.0 * ppm * 0.01)
        circles[1].getAttribute("r").toDouble() shouldBe (15.0 * ppm plusOrMinus 15.0 * ppm * 0.02)
        val width = svg.getAttribute("width").toDouble()
        val height = svg.getAttribute("height").toDouble()
        val big = circles[0]
        val (cx, cy, r) = listOf("cx", "cy", "r").map { big.getAttribute(it).toDouble() }
        (cx - r >= 0 && cx + r <= width && cy - r >= 0 && cy + r <= height) shouldBe true
        val mission = svg.group("plan-mission")
        mission.elements("polyline").single().getAttribute("points").split(" ").size shouldBe 3
        mission.elements("circle").size shouldBe 3
        svg.group("homes").elements("rect").size shouldBe 1
        svg.group("legend").elements("g").map { it.getAttribute("data-layer") } shouldBe listOf("fence", "fence", "plan-mission", "homes", "rally")
    }

    test("a mission's altitudes are above mean sea level when the plan has a home, and said to be relative when it has none") {
        val withHome = MapFeatures.of(plan).single { it.properties["kind"] == MapFeatures.MISSION }
        (withHome.shape as GeoShape.Line).points.map { it.altitude.meters } shouldBe listOf(508.0, 518.0, 518.0)
        withHome.properties["items"] shouldBe 3L
        val without = MapFeatures.mission(plan.mission).single()
        (without.shape as GeoShape.Line).points.map { it.altitude.meters } shouldBe listOf(20.0, 30.0, 30.0)
        without.properties["altitude"] shouldBe "relative to home"
        MapFeatures.of(plan).filter { it.properties["kind"] == MapFeatures.RALLY }.map { (it.shape as GeoShape.Point).at.altitude.meters } shouldBe listOf(513.0, 513.0)
    }

    val location = arbitrary { Location(Arb.double(-60.0..60.0, includeNaNs = false).bind(), Arb.double(-170.0..170.0, includeNaNs = false).bind(), Arb.double(0.0..3000.0, includeNaNs = false).bind().m) }
    val randomPlan = arbitrary {
        val centre = location.bind()
        val offsets = Arb.list(Arb.double(-2000.0..2000.0, includeNaNs = false), 40..40).bind().iterator() // 2 per place, at most 17 places
        fun near() = centre.offset(offsets.next().m, offsets.next().m)
        QgcPlan(
            mission = List(Arb.int(0..8).bind()) { waypoint(it, near(), Arb.int(5..120).bind().toFloat()) },
            geoFence = PlanGeoFence(
                polygons = List(Arb.int(0..3).bind()) { FencePolygon(Arb.boolean().bind(), square(near(), Arb.double(5.0..500.0, includeNaNs = false).bind())) },
                circles = List(Arb.int(0..3).bind()) { FenceCircle(Arb.boolean().bind(), point(near()), Arb.double(1.0..900.0, includeNaNs = false).bind()) },
            ),
            rallyPoints = List(Arb.int(0..3).bind()) { near().let { PlanPosition(it.latitude, it.longitude, Arb.double(0.0..80.0, includeNaNs = false).bind()) } },
            plannedHome = if (Arb.boolean().bind()) PlanPosition(centre.latitude, centre.longitude, centre.altitude.meters) else null,
        )
    }
    val randomTrack = arbitrary {
        val start = location.bind()
        FlownTrack(Arb.int(1..250).bind(), VehicleType.QUADROTOR, List(Arb.int(0..30).bind()) { start.offset((it * 7).m, (it * 3).m, it.m) }, emptyList(), if (Arb.boolean().bind()) start else null)
    }

    test("a plan's waypoints carry their item numbers as QGC lists them (the take-off, with no position, is 1)") {
        val svg = parse(FlightMap("field").plan(plan).svg())
        svg.group("plan-mission").elements("text").map { it.textContent } shouldBe listOf("2", "3", "4")
    }

    test("a planned home at 0°, 0° is one the file's writer did not know: not drawn, and the map stays around the mission") {
        val unknownHome = plan.copy(plannedHome = PlanPosition(0.0, 0.0, 0.0))
        MapFeatures.of(unknownHome).filter { it.properties["kind"] == MapFeatures.HOME } shouldBe emptyList()
        MapFeatures.of(unknownHome).single { it.properties["kind"] == MapFeatures.MISSION } shouldBe
            MapFeatures.of(plan.copy(plannedHome = null)).single { it.properties["kind"] == MapFeatures.MISSION }
    }

    test("a map written as GeoJSON and read back has the same features, and draws the same SVG") {
        checkAll(150, randomPlan, Arb.list(randomTrack, 0..3)) { p, tracks ->
            val map = FlightMap("round trip").plan(p)
            tracks.forEach(map::track)
            val back = FlightMap("round trip").add(GeoJson.read(map.geoJson()))
            back.features shouldBe map.features
            back.svg() shouldBe map.svg()
        }
    }

    test("KML draws a circular fence as a closed ring at its radius, and the document is well-formed") {
        val kml = FlightMap("field & more").plan(plan).kml()
        val doc = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(kml.byteInputStream()).documentElement
        val placemarks = doc.elements("Placemark")
        placemarks.size shouldBe MapFeatures.of(plan).size
        val circle = placemarks.single { it.elements("name").single().textContent == "fence circle 1" }
        val ring = circle.elements("coordinates").single().textContent.trim().split(" ").map { c -> c.split(",").map(String::toDouble).let { Location(it[1], it[0]) } }
        ring.size shouldBe 73
        ring.first() shouldBe ring.last()
        ring.forEach { it.distanceTo(Location(home.latitude, home.longitude)).meters shouldBe (300.0 plusOrMinus 0.5) }
    }

    test("the map's format is its file's extension") {
        MapFormat.of(Path.of("a/field.SVG")) shouldBe MapFormat.SVG
        MapFormat.of(Path.of("field.geojson")) shouldBe MapFormat.GEOJSON
        MapFormat.of(Path.of("field.json")) shouldBe MapFormat.GEOJSON
        MapFormat.of(Path.of("field.kml")) shouldBe MapFormat.KML
        shouldThrow<MapFormatUnknown> { MapFormat.of(Path.of("field.png")) }
        shouldThrow<MapFormatUnknown> { MapFormat.of(Path.of("field")) }
    }
})
