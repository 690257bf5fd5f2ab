package pod.launch.geo

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.filter
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.string
import io.kotest.property.checkAll
import pod.core.units.Location
import pod.core.units.m
import javax.xml.parsers.DocumentBuilderFactory

private val location = arbitrary {
    Location(Arb.double(-89.9, 89.9).filter { it.isFinite() }.bind(), Arb.double(-179.9, 179.9).filter { it.isFinite() }.bind(), Arb.double(-400.0, 9000.0).filter { it.isFinite() }.bind().m)
}

private val shape = arbitrary<GeoShape> {
    when (Arb.int(0..2).bind()) {
        0 -> GeoShape.Point(location.bind())
        1 -> GeoShape.Line(Arb.list(location, 2..30).bind())
        else -> GeoShape.Polygon(Arb.list(location, 3..30).bind().distinct().let { if (it.size >= 3) it else it + List(3 - it.size) { i -> Location(i * 1.0, 1.0) } })
    }
}

private val value = arbitrary<Any> {
    when (Arb.int(0..3).bind()) {
        0 -> Arb.string(0..20).bind()
        1 -> Arb.long().bind()
        2 -> Arb.double().bind().takeIf { it.isFinite() && it != Math.rint(it) } ?: 0.5
        else -> Arb.boolean().bind()
    }
}

private val feature = arbitrary {
    GeoFeature(shape.bind(), Arb.list(arbitrary { Arb.string(1..8).bind() to value.bind() }, 0..5).bind().toMap())
}

class GeoExportTest : FunSpec({
    test("GeoJSON: what is written reads back equal (shapes, positions, altitudes, properties)") {
        checkAll(300, Arb.list(feature, 0..8)) { features ->
            GeoJson.read(GeoJson.write(features)) shouldBe features
        }
    }

    test("GeoJSON positions are longitude first and a polygon's ring is closed, as RFC 7946 says") {
        val a = Location(41.1, -8.6, 12.m)
        val text = GeoJson.write(listOf(GeoFeature(GeoShape.Polygon(listOf(a, Location(41.2, -8.6), Location(41.2, -8.5))), mapOf("kind" to "fence"))))
        val compact = text.filterNot { it.isWhitespace() }
        compact shouldContain "[-8.6,41.1,12.0]"
        Regex("""\[-8\.6,41\.1,12\.0]""").findAll(compact).count() shouldBe 2 // first and last of the ring
    }

    test("GeoJSON that Pod cannot read fails typed, naming what is wrong") {
        shouldThrow<GeoJsonException> { GeoJson.read("{") }.message shouldContain "not JSON"
        shouldThrow<GeoJsonException> { GeoJson.read("""{"type":"Topology"}""") }.message shouldContain "FeatureCollection"
        shouldThrow<GeoJsonException> { GeoJson.read("""{"type":"Feature","geometry":{"type":"Point","coordinates":[1]}}""") }.message shouldContain "longitude and a latitude"
        shouldThrow<GeoJsonException> { GeoJson.read("""{"type":"Feature","geometry":{"type":"LineString","coordinates":[[1,2]]}}""") }.message shouldContain "at least 2 points"
        shouldThrow<GeoJsonException> { GeoJson.read("""{"type":"Feature","geometry":{"type":"Point","coordinates":[1,200]}}""") }.message shouldContain "feature"
    }

    test("KML is well-formed XML with a Placemark per feature, coordinates longitude first, in any locale") {
        val previous = java.util.Locale.getDefault()
        java.util.Locale.setDefault(java.util.Locale.GERMANY)
        try {
            checkAll(100, Arb.list(feature, 1..6)) { features ->
                val kml = Kml.write(features, "a <plan> & its track")
                val doc = DocumentBuilderFactory.newInstance().apply { isNamespaceAware = true }.newDocumentBuilder().parse(kml.byteInputStream())
                doc.getElementsByTagName("Placemark").length shouldBe features.size
                val first = doc.getElementsByTagName("coordinates").item(0).textContent.trim().split(" ").first().split(",")
                val expected = when (val s = features.first().shape) {
                    is GeoShape.Point -> s.at
                    is GeoShape.Line -> s.points.first()
                    is GeoShape.Polygon -> s.vertices.first()
                }
                first.size shouldBe 3
                (kotlin.math.abs(first[0].toDouble() - expected.longitude) < 1e-7) shouldBe true
                (kotlin.math.abs(first[1].toDouble() - expected.latitude) < 1e-7) shouldBe true
            }
        } finally {
            java.util.Locale.setDefault(previous)
        }
    }
})
