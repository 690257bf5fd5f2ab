package pod.sim.world

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import pod.core.units.m
import pod.sim.SimVehicleConfig
import kotlin.math.abs
import kotlin.math.exp

class TerrainTest : StringSpec({
    val origin = SimVehicleConfig.DEFAULT_HOME

    "a seeded terrain is the same for the same seed, everywhere, and another seed gives another" {
        checkAll(50, Arb.long(), Arb.double(-400.0, 400.0, includeNaNs = false), Arb.double(-400.0, 400.0, includeNaNs = false)) { seed, n, e ->
            val a = Terrain.seeded(seed, origin)
            val b = Terrain.seeded(seed, origin)
            a shouldBe b
            val at = origin.offset(n.m, e.m)
            a.elevationAt(at) shouldBe b.elevationAt(at)
        }
        Terrain.seeded(1, origin) shouldNotBe Terrain.seeded(2, origin)
    }

    "a seeded terrain is smooth: its slope is bounded by the plane's and the hills' steepest flanks, and it has no kinks" {
        checkAll(30, Arb.long()) { seed ->
            val terrain = Terrain.seeded(seed, origin, hillCount = 6)
            // A Gaussian bump of height h and width r is steepest at r: h/r·e^(-1/2).
            val bound = abs(terrain.slopeNorth) + abs(terrain.slopeEast) + terrain.hills.sumOf { abs(it.height.meters) / it.radius.meters * exp(-0.5) }
            val step = 0.5
            for (i in -40..40) {
                for (j in listOf(-150.0, 0.0, 150.0)) {
                    val p = origin.offset((i * 10.0).m, j.m)
                    val z0 = terrain.elevationAt(p).meters
                    val zn = terrain.elevationAt(p.offset(step.m, 0.m)).meters
                    val zs = terrain.elevationAt(p.offset((-step).m, 0.m)).meters
                    abs(zn - z0) / step shouldBeLessThan bound * 1.01 + 1e-9
                    // Second difference: a smooth surface bends little over half a metre.
                    abs(zn - 2 * z0 + zs) shouldBeLessThan 0.05
                }
            }
        }
    }

    "an explicit hill stands at its place and height, and the ground far from it is the tilted plane" {
        val terrain = Terrain(origin, listOf(Hill(100.m, (-50).m, 12.m, 20.m)), slopeNorth = 0.01)
        terrain.elevationAt(origin.offset(100.m, (-50).m)).meters shouldBe (origin.altitude.meters + 1.0 + 12.0 plusOrMinus 1e-3)
        terrain.elevationAt(origin.offset(20.m, 300.m)).meters shouldBe (origin.altitude.meters + 0.2 plusOrMinus 1e-3)
        terrain.elevationAt(origin).meters shouldBe (origin.altitude.meters plusOrMinus 1e-4) // the hill's tail: 12 m·e^(-15.6)
    }

    "a camera's field of view follows from its sensor and lens" {
        CameraFov.DEFAULT.horizontal.degrees shouldBe (73.74 plusOrMinus 0.01)
        CameraFov.DEFAULT.vertical.degrees shouldBe (53.13 plusOrMinus 0.01)
    }
})
