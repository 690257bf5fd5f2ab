package pod.launch

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.comparables.shouldBeLessThanOrEqualTo
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import org.w3c.dom.Element
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.survey.CameraTrigger
import pod.core.survey.PolygonSurvey
import pod.core.survey.SurveyPlan
import pod.core.survey.SurveySpacing
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import java.util.Locale
import javax.xml.parsers.DocumentBuilderFactory
import kotlin.math.cos
import kotlin.math.sin
import kotlin.random.Random

class SurveyMapTest : StringSpec({
    val base = Location(47.397, 8.545)

    // An L-shaped (concave) field with turnarounds and a photo per waypoint: the plan has
    // photographed legs, turnaround legs and transit bends.
    val field = listOf(
        base, base.offset(0.m, 120.m), base.offset(60.m, 120.m), base.offset(60.m, 50.m),
        base.offset(140.m, 50.m), base.offset(140.m, 0.m),
    )
    val plan = PolygonSurvey.plan(
        field, height = 30.m, spacing = SurveySpacing.Direct(20.m), trackAngle = 90.deg,
        turnaround = 10.m, trigger = CameraTrigger.PER_WAYPOINT,
    )
    val photoIndices = plan.waypoints.indices.filter { plan.waypoints[it].photo }
    val flagged = photoIndices.filterIndexed { n, _ -> n % 3 == 1 }
    val backward = flagged.reversed()
    val objects = listOf(base.offset(30.m, 30.m), base.offset(100.m, 20.m), base.offset(200.m, -40.m))
    val track = plan.locations + backward.map { plan.waypoints[it].location }
    fun picture() = SurveyPicture(field, plan, flagged, backward, "Copter 1", objects, track, vehicleId = 2)

    "the survey map is XML with one element per waypoint, detection, object and backward stop" {
        withClue("the plan must exercise every layer") {
            flagged.size shouldBeGreaterThan 2
            plan.waypoints.count { it.turnaround || it.transit } shouldBeGreaterThan 0
        }
        val svg = parse(surveySvg(picture(), "I-Seed survey"))

        svg.layer("survey-area").all("polygon").single().points().size shouldBe field.size
        svg.layer("photo-waypoints").all("circle").map { it.getAttribute("data-waypoint").toInt() } shouldContainExactly photoIndices
        svg.layer("detections").all("circle").map { it.getAttribute("data-waypoint").toInt() } shouldContainExactly flagged
        svg.layer("objects").all("path").size shouldBe objects.size
        svg.layer("flown").all("polyline").single().points().size shouldBe track.size

        val forward = svg.layer("forward-path").all("polyline")
        forward.filter { it.getAttribute("class") == "track-leg" }.size shouldBeGreaterThan 0
        forward.filter { it.getAttribute("class") == "turn-leg" }.size shouldBeGreaterThan 0
        // Consecutive runs share their joining waypoint: together they pass every waypoint once.
        forward.sumOf { it.points().size } - (forward.size - 1) shouldBe plan.waypoints.size

        val back = svg.layer("backward-path")
        val stops = back.all("circle")
        stops.map { it.getAttribute("data-waypoint").toInt() } shouldContainExactly backward
        back.all("polyline").single().points() shouldContainExactly stops.map { it.number("cx") to it.number("cy") }
        back.all("text").map { it.textContent } shouldContainExactly backward.indices.map { "${it + 1}" }
        back.all("text").map { it.getAttribute("data-waypoint").toInt() } shouldContainExactly backward
    }

    "the backward path is drawn in the order flown, not the plan's order" {
        val order = listOf(flagged[2], flagged[0], flagged[1])
        val svg = parse(surveySvg(SurveyPicture(field, plan, flagged, order, "Copter 1"), "order"))
        val stops = svg.layer("backward-path").all("circle")
        stops.map { it.getAttribute("data-waypoint").toInt() } shouldContainExactly order
        val first = plan.waypoints[order[0]].location
        val second = plan.waypoints[order[1]].location
        // North is up: the stop further north has the smaller y.
        (stops[0].number("cy") < stops[1].number("cy")) shouldBe (first.latitude > second.latitude)
    }

    "the legend names every layer drawn and the vehicle" {
        val svg = parse(surveySvg(picture(), "legend"))
        val drawn = svg.all("g").map { it.getAttribute("id") }.filter { it.isNotEmpty() && it != "legend" && it != "scale-bar" }
        drawn shouldContainAll listOf("survey-area", "forward-path", "photo-waypoints", "flown", "objects", "detections", "backward-path")
        // The flown track (which follows the plan) lies under the forward path, not over it.
        (drawn.indexOf("flown") < drawn.indexOf("forward-path")) shouldBe true
        val entries = svg.layer("legend").all("g").filter { it.getAttribute("class") == "legend-entry" }
        entries.map { it.getAttribute("data-layer") } shouldContainAll drawn
        val vehicle = entries.single { it.getAttribute("data-layer") == "vehicle-2" }
        vehicle.all("text").single().textContent shouldBe "Copter 1"
    }

    "a survey without detections draws no detection or backward layer and no legend entry for them" {
        val svg = parse(surveySvg(SurveyPicture(field, plan, emptyList(), emptyList(), "Copter 1"), "nothing found"))
        val ids = svg.all("g").map { it.getAttribute("id") }
        ids.contains("detections") shouldBe false
        ids.contains("backward-path") shouldBe false
        svg.layer("legend").all("g").map { it.getAttribute("data-layer") }.any { it == "detections" || it == "backward-path" } shouldBe false
    }

    "everything drawn lies within the fitted canvas, whatever the survey's size and shape" {
        checkAll(40, Arb.long(), Arb.double(15.0, 3000.0, includeNaNs = false), Arb.double(0.05, 20.0, includeNaNs = false), Arb.int(0..179)) { seed, size, stretch, angle ->
            val random = Random(seed)
            // A star-shaped polygon (vertices sorted by bearing) stretched north-south: simple, and
            // anything from a thin north-south strip to a flat east-west one.
            val vertices = (0 until 7).map { i ->
                val bearing = 2 * Math.PI * (i + random.nextDouble(0.1, 0.9)) / 7
                val r = size * random.nextDouble(0.4, 1.0)
                base.offset((r * cos(bearing) * stretch).m, (r * sin(bearing)).m)
            }
            val survey = PolygonSurvey.plan(vertices, 40.m, SurveySpacing.Direct((size * minOf(stretch, 1.0) / 4).m), angle.deg, turnaround = (size / 20).m)
            val photos = survey.waypoints.indices.filter { survey.waypoints[it].photo }
            val hits = photos.filter { random.nextBoolean() }
            val scattered = List(5) { base.offset((size * random.nextDouble(-2.0, 2.0)).m, (size * random.nextDouble(-2.0, 2.0)).m) }
            val svg = parse(surveySvg(SurveyPicture(vertices, survey, hits, hits.shuffled(random), "v", scattered, survey.locations), "t"))
            svg.shouldFitItsViewBox()
            // Fitted: the canvas leaves at most the margins, the legend column and the title and
            // scale bands blank, and the smaller side is not padded out to a fixed size.
            val (width, height) = svg.viewBox()
            val content = svg.contentPoints()
            width - (content.maxOf { it.first } - content.minOf { it.first }) shouldBeLessThanOrEqualTo 370.0
            height - (content.maxOf { it.second } - content.minOf { it.second }) shouldBeLessThanOrEqualTo 370.0
        }
    }

    "the numbers are written with a decimal point whatever the default locale" {
        val saved = Locale.getDefault()
        try {
            Locale.setDefault(Locale.GERMANY)
            parse(surveySvg(picture(), "Feld")).shouldFitItsViewBox()
        } finally {
            Locale.setDefault(saved)
        }
    }

    "the fleet map keeps its planned and flown layers and names each vehicle in the legend" {
        val hop = Mission("hop", base, listOf(MissionStep.Waypoint(base.offset(0.m, 0.m, 20.m)), MissionStep.Waypoint(base.offset(300.m, 10.m, 20.m))))
        val tracks = mapOf(
            1 to ("Copter 1" to listOf(base, base.offset(150.m, 5.m), base.offset(300.m, 10.m))),
            3 to ("Plane 3" to listOf(base.offset(-5.m, 0.m), base.offset(-5.m, 400.m))),
        )
        val map = parse(svg(listOf(1 to hop, 3 to hop), tracks, "fleet"))
        map.layer("planned").all("polyline").size shouldBe 2
        map.layer("flown").all("polyline").map { it.getAttribute("class") } shouldContainExactly listOf("vehicle-1", "vehicle-3")
        val legend = map.layer("legend").all("g").associate { it.getAttribute("data-layer") to it.textContent.trim() }
        legend["vehicle-1"] shouldContain "Copter 1"
        legend["vehicle-3"] shouldContain "Plane 3"
        legend.keys shouldContainAll listOf("planned", "flown")
        map.shouldFitItsViewBox()
    }

    "a detection is named by the number the map shows for its backward stop, and by its forward waypoint counted from 1" {
        val svg = parse(surveySvg(picture(), "I-Seed survey"))
        val shown = svg.layer("backward-path").all("text").associate { it.getAttribute("data-waypoint").toInt() to it.textContent }
        for (ring in svg.layer("detections").all("circle")) {
            val i = ring.getAttribute("data-waypoint").toInt()
            ring.textContent shouldBe "backward stop ${shown.getValue(i)} (forward waypoint ${i + 1}) detected something"
        }
    }

    "vehicles ending at a shared home get labels that do not overlap; a home without a track is in the legend; planned items are numbered" {
        val hop = Mission("hop", base, listOf(MissionStep.Waypoint(base.offset(100.m, 0.m, 20.m)), MissionStep.Waypoint(base.offset(300.m, 10.m, 20.m))))
        val tracks = (1..3).associateWith { id -> "Copter $id" to listOf(base.offset((100 * id).m, 0.m), base) }
        val homes = mapOf(1 to base, 2 to base, 3 to base, 4 to base.offset(-20.m, 0.m))
        val map = parse(svg(listOf(1 to hop), tracks, "fleet", homes))
        val labels = map.layer("flown").all("text").map { it.number("x") to it.number("y") }
        labels.size shouldBe 3
        labels.distinct().size shouldBe 3
        for ((a, b) in labels.flatMapIndexed { i, a -> labels.drop(i + 1).map { a to it } }) {
            withClue("$a and $b") { (kotlin.math.abs(a.second - b.second) >= 12.0) shouldBe true }
        }
        val legend = map.layer("legend").all("g").map { it.getAttribute("data-layer") }
        legend shouldContainAll listOf("vehicle-1", "vehicle-2", "vehicle-3", "vehicle-4")
        map.layer("planned").all("text").map { it.textContent } shouldContainExactly listOf("1", "2")
        map.shouldFitItsViewBox()
    }

    "a picture refuses waypoint indices outside its plan" {
        shouldThrow<IllegalArgumentException> { SurveyPicture(field, plan, listOf(plan.waypoints.size), emptyList(), "v") }
            .message shouldContain "forwardFlagged"
        shouldThrow<IllegalArgumentException> { SurveyPicture(field, plan, emptyList(), listOf(-1), "v") }
            .message shouldContain "backwardOrder"
        shouldThrow<IllegalArgumentException> { SurveyPicture(field, plan, listOf(flagged[0], flagged[0]), emptyList(), "v") }
            .message shouldContain "repeat"
        shouldThrow<IllegalArgumentException> { SurveyPicture(field.take(2), plan, emptyList(), emptyList(), "v") }
            .message shouldContain "polygon"
    }
})

private fun parse(svg: String): Element =
    DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(svg.byteInputStream()).documentElement

private fun Element.all(tag: String): List<Element> {
    val nodes = getElementsByTagName(tag)
    return (0 until nodes.length).map { nodes.item(it) as Element }
}

private fun Element.layer(id: String): Element = all("g").single { it.getAttribute("id") == id }

private fun Element.number(name: String): Double = getAttribute(name).toDouble()

private fun Element.points(): List<Pair<Double, Double>> =
    getAttribute("points").trim().split(Regex("\\s+")).map { p -> p.split(',').let { it[0].toDouble() to it[1].toDouble() } }

private fun Element.viewBox(): Pair<Double, Double> =
    getAttribute("viewBox").split(' ').map { it.toDouble() }.let { (x, y, w, h) ->
        (x to y) shouldBe (0.0 to 0.0)
        w to h
    }

/** Every coordinate drawn: circle centres, text anchors, line ends, polyline/polygon points, path points. */
private fun Element.drawnPoints(): List<Pair<Double, Double>> = buildList {
    for (e in all("*")) {
        fun has(a: String) = e.hasAttribute(a)
        if (has("cx")) add(e.number("cx") to e.number("cy"))
        if (has("x") && has("y")) add(e.number("x") to e.number("y"))
        if (has("x1")) {
            add(e.number("x1") to e.number("y1"))
            add(e.number("x2") to e.number("y2"))
        }
        if (has("points")) addAll(e.points())
        if (has("d")) {
            addAll(Regex("(-?[0-9.]+),(-?[0-9.]+)").findAll(e.getAttribute("d")).map { it.groupValues[1].toDouble() to it.groupValues[2].toDouble() })
        }
    }
}

/** The points of the map's content (not the title, legend or scale bar). */
private fun Element.contentPoints(): List<Pair<Double, Double>> =
    all("g").filter { it.getAttribute("id") !in setOf("", "legend", "scale-bar") && it.getAttribute("class") != "legend-entry" }
        .flatMap { it.drawnPoints() }

private fun Element.shouldFitItsViewBox() {
    val (width, height) = viewBox()
    val points = drawnPoints()
    points.size shouldBeGreaterThan 0
    for ((x, y) in points) {
        withClue("($x, $y) within 0..$width × 0..$height") {
            (x in 0.0..width && y in 0.0..height) shouldBe true
        }
    }
}
