package example.fleet

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.int
import io.kotest.property.checkAll
import pod.core.mission.MissionCompletion
import pod.core.mission.MissionStep
import pod.core.units.Location
import pod.core.units.m
import pod.dsl.mission
import pod.test.mission

/**
 * A user's property tests with kotest and pod-test. (ConsumerBuildSpec also copies the README's
 * pod-test example into this project's tests: every spec here must run and pass.)
 */
class HopSpec : StringSpec({
    "any mission pod-test draws takes off first and ends landed" {
        checkAll(Arb.mission(Location(41.178, -8.596, 0.m), radius = 150.m)) { drawn ->
            (drawn.steps.first() is MissionStep.TakeOff) shouldBe true
            drawn.completion shouldBe MissionCompletion.LANDED
        }
    }

    "for any home, height and leg, the mission takes off first, climbs to the height and ends landed at home" {
        checkAll(
            Arb.double(-60.0, 60.0, includeNaNs = false),
            Arb.double(-170.0, 170.0, includeNaNs = false),
            Arb.int(5..120),
            Arb.int(-500..500),
        ) { latitude, longitude, height, north ->
            val built = mission("leg") {
                home(Location(latitude, longitude, 0.m))
                takeOff(height.m)
                move(north = north.m)
                returnHomeAndLand()
            }
            (built.steps.first() is MissionStep.TakeOff) shouldBe true
            (built.steps.first() as MissionStep.TakeOff).location.altitude shouldBe height.m
            built.completion shouldBe MissionCompletion.LANDED
        }
    }

    "the program's hop is the same mission wherever home is" {
        checkAll(Arb.double(-60.0, 60.0, includeNaNs = false)) { latitude ->
            hop(Location(latitude, 10.0, 0.m)).steps.size shouldBe hop(Location(0.0, 0.0, 0.m)).steps.size
        }
    }
})
