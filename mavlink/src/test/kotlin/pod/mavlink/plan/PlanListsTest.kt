package pod.mavlink.plan

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.checkAll
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import kotlin.math.roundToLong

private fun onWire(degrees: Double): Double = (degrees * 1e7).roundToLong() / 1e7

private fun PlanPoint.onWire() = PlanPoint(onWire(latitude), onWire(longitude))

private val fences: Arb<PlanGeoFence> = arbitrary { rs ->
    val r = rs.random
    fun point() = PlanPoint(r.nextDouble(-90.0, 90.0), r.nextDouble(-180.0, 180.0))
    PlanGeoFence(
        polygons = List(r.nextInt(0, 4)) { FencePolygon(r.nextBoolean(), List(r.nextInt(3, 8)) { point() }) },
        circles = List(r.nextInt(0, 4)) { FenceCircle(r.nextBoolean(), point(), r.nextInt(1, 100_000).toDouble()) },
    )
}

class PlanListsTest : StringSpec({
    "a fence becomes FENCE items and back, rounded only to the wire's 1e-7 degree" {
        checkAll(PropTestConfig(seed = 16), fences) { fence ->
            val items = PlanLists.fenceItems(fence)
            items.map { it.seq } shouldBe items.indices.toList()
            items.all { it.missionType == MissionType.FENCE } shouldBe true
            items.size shouldBe fence.polygons.sumOf { it.vertices.size } + fence.circles.size
            PlanLists.fence(items) shouldBe PlanGeoFence(
                polygons = fence.polygons.map { p -> p.copy(vertices = p.vertices.map { it.onWire() }) },
                circles = fence.circles.map { c -> c.copy(center = c.center.onWire()) },
            )
        }
    }

    "rally points become RALLY items in the relative-altitude frame and back" {
        val points = listOf(PlanPosition(47.1234567, 8.7654321, 30.0), PlanPosition(-35.0, 149.0, 12.5))
        val items = PlanLists.rallyItems(points)
        items.map { it.command } shouldBe listOf(5100, 5100)
        items.map { it.frame } shouldBe listOf(3, 3)
        items[0].x shouldBe 471_234_567
        PlanLists.rallyPoints(items) shouldBe points
    }

    "a FENCE list whose polygon is cut short or holds a foreign command is refused with the item's seq" {
        val polygon = PlanLists.fenceItems(
            PlanGeoFence(polygons = listOf(FencePolygon(true, List(4) { PlanPoint(47.0 + it * 0.001, 8.0) }))),
        )
        shouldThrow<PlanListException> { PlanLists.fence(polygon.dropLast(1)) }.reason shouldContain "runs past"
        val foreign = polygon.toMutableList().also { it[2] = it[2].copy(command = 5002) }
        shouldThrow<PlanListException> { PlanLists.fence(foreign) }.seq shouldBe 2
        shouldThrow<PlanListException> {
            PlanLists.fence(listOf(MissionItem(seq = 0, frame = 0, command = 16)))
        }.reason shouldContain "command 16"
    }
})
