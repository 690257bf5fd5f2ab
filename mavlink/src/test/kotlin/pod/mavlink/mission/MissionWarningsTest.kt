package pod.mavlink.mission

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.MavFrames

class MissionWarningsTest : StringSpec({
    val home = Location(41.1785, -8.5957, 120.m)
    fun at(seq: Int, north: Double, alt: Float, frame: Int = MavFrames.GLOBAL_RELATIVE_ALT, command: Int = 16) = home.offset(north.m, 0.m).let {
        MissionItem(seq, frame, command, x = Math.round(it.latitude * 1e7).toInt(), y = Math.round(it.longitude * 1e7).toInt(), z = alt)
    }

    "a plain survey near home says nothing" {
        MissionWarnings.of((1..5).map { at(it, 100.0 * it, 30f) }, home) shouldBe emptyList()
    }

    "below home, relative or above sea level; far from home; far from the item before" {
        MissionWarnings.of(listOf(at(1, 100.0, -20f), at(2, 200.0, 100f, frame = MavFrames.GLOBAL)), home) shouldBe listOf(
            "item 1 is 20 m below home", "item 2 is 20 m below home",
        )
        MissionWarnings.of(listOf(at(1, 100.0, 20f), at(2, 7_700.0, 20f)), home) shouldBe listOf(
            "item 2 is 7.7 km from home", "item 2 is 7.6 km from item 1 before it",
        )
    }

    "without a home only the steps between items are measured; items without a position are skipped" {
        val takeoff = MissionItem(1, MavFrames.GLOBAL_RELATIVE_ALT, 22, z = 20f)
        MissionWarnings.of(listOf(takeoff, at(2, 0.0, 20f, frame = MavFrames.GLOBAL), at(3, 6_000.0, 20f)), null) shouldBe listOf(
            "item 3 is 6.0 km from item 2 before it",
        )
    }
})
