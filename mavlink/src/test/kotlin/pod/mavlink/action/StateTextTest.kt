package pod.mavlink.action

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldNotContain
import pod.core.units.Location
import pod.core.units.Speed
import pod.core.units.m
import pod.core.vehicle.LandedState
import pod.core.vehicle.Position

class StateTextTest : StringSpec({
    "what an unconfirmed action saw last reads as words, never a data class's toString" {
        val p = Position(Location(41.0, -8.0, 120.m), 0.04.m, null, Speed(0.0), Speed(0.0), Speed(0.0))
        heightText(p) shouldBe "at 0.0 m above home"
        stateText(p) shouldNotContain "Position("
        stateText(LandedState.ON_GROUND to false) shouldBe "on ground, disarmed"
        stateText(null) shouldBe "nothing"
        ActionNotConfirmed("takeoff to 20.0 m", "altitude ≥ 19.0 m", heightText(p), kotlin.time.Duration.parse("2m")).message shouldBe
            "takeoff to 20.0 m was accepted but the vehicle did not show altitude ≥ 19.0 m within 2 min (last seen: at 0.0 m above home)"
    }
})
