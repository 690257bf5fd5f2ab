package pod.mavlink.executor

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlin.math.cos
import kotlin.math.sin
import pod.core.mission.LoiterDuration
import pod.core.mission.MissionStep
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.units.mps
import pod.core.vehicle.Position

class CircleWatchTest : StringSpec({
    val center = Location(41.15, -8.61, 50.m)
    val loiter = MissionStep.Loiter(center, 80.m, LoiterDuration.Unlimited)

    fun at(north: Double, east: Double, vn: Double, ve: Double, height: Double = 50.0) = Position(
        center.offset(north.m, east.m).copy(altitude = (100 + height).m), height.m, 0.deg, vn.mps, ve.mps, 0.mps,
    )

    "a plane flying straight at the loiter point is never established, however close it passes" {
        val watch = CircleWatch(loiter)
        (300 downTo -300 step 5).map { n -> watch.established(at(n.toDouble(), 0.0, -15.0, 0.0)) }.any { it } shouldBe false
    }

    "a plane on the circle is established once it has flown a quarter of it, not before" {
        val watch = CircleWatch(loiter)
        val results = (0..120 step 5).map { deg ->
            val a = Math.toRadians(deg.toDouble())
            // Clockwise seen from above: velocity along the tangent.
            watch.established(at(80 * cos(a), 80 * sin(a), -15 * sin(a), 15 * cos(a)))
        }
        results.indexOfFirst { it } shouldBe 18 // 90° after the first sample
        results.last() shouldBe true
    }

    "a plane circling well below the loiter's height is not established" {
        val watch = CircleWatch(loiter)
        (0..360 step 5).map { deg ->
            val a = Math.toRadians(deg.toDouble())
            watch.established(at(80 * cos(a), 80 * sin(a), -15 * sin(a), 15 * cos(a), height = 20.0))
        }.any { it } shouldBe false
    }
})
