package pod.launch

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import pod.core.units.Location
import pod.core.units.m
import javax.xml.parsers.DocumentBuilderFactory
import org.w3c.dom.Element

class FleetMapTest : FunSpec({
    test("a fleet map marks each vehicle's home, names each flown track at its end, and says what a home looks like in the legend") {
        val home1 = Location(41.0, -8.0, 10.m)
        val home2 = home1.offset(0.m, 5.m)
        val track1 = listOf(home1, home1.offset(100.m, 0.m), home1.offset(100.m, 80.m))
        val track2 = listOf(home2, home2.offset(-50.m, 40.m))
        val doc = DocumentBuilderFactory.newInstance().newDocumentBuilder()
            .parse(svg(emptyList(), mapOf(1 to ("copter-1" to track1), 2 to ("copter-2" to track2)), "two", mapOf(1 to home1, 2 to home2)).byteInputStream()).documentElement
        fun group(id: String): Element = (0 until doc.getElementsByTagName("g").length).map { doc.getElementsByTagName("g").item(it) as Element }.single { it.getAttribute("id") == id }
        group("homes").getElementsByTagName("rect").length shouldBe 2
        val labels = group("flown").getElementsByTagName("text")
        (0 until labels.length).map { labels.item(it).textContent }.sorted() shouldBe listOf("copter-1", "copter-2")
        // Each name sits beside its track's last point: the north-east end for copter-1, south-east for copter-2.
        val y = (0 until labels.length).associate { labels.item(it).textContent to (labels.item(it) as Element).getAttribute("y").toDouble() }
        (y.getValue("copter-1") < y.getValue("copter-2")) shouldBe true
        group("legend").textContent.contains("home") shouldBe true
    }
})
