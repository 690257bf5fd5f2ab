package pod.sim.autopilot

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThanOrEqual
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.units.m
import pod.sim.flight.Body
import pod.sim.flight.FixedWingAirframe
import pod.sim.flight.Guidance
import pod.sim.flight.MultirotorAirframe
import pod.sim.flight.Performance
import pod.sim.flight.atAltitude
import pod.sim.flight.horizontalDistance
import kotlin.math.hypot

class FlightModelTest : StringSpec({
    val ground = HOME.altitude.meters
    val copter = Performance(cruise = 5.0, climb = 2.5, descent = 1.5, landSpeed = 0.5)
    val plane = Performance(cruise = 15.0, climb = 5.0, descent = 5.0, minAirspeed = 9.0, maxAirspeed = 22.0, bankLimit = 45.0, loiterRadius = 60.0)

    fun fly(body: Body, guidance: Guidance, perf: Performance, seconds: Double, model: pod.sim.flight.Airframe, check: (Body) -> Unit = {}): Body {
        var b = body
        repeat((seconds / DT).toInt()) {
            b = model.step(b, guidance, perf, ground, true, DT)
            check(b)
        }
        return b
    }

    "a multirotor climbs at its climb rate to the take-off altitude and then hovers there" {
        var maxClimb = 0.0
        var b = fly(Body(HOME), Guidance.Climb(ground + 20), copter, 12.0, MultirotorAirframe) { maxClimb = maxOf(maxClimb, -it.velocityDown) }
        b.location.altitude.meters shouldBe ((ground + 20) plusOrMinus 0.1)
        maxClimb shouldBeLessThan 2.5 + 1e-9
        val hoverAt = b.location
        b = fly(b, Guidance.Loiter(hoverAt, 0.0), copter, 30.0, MultirotorAirframe)
        horizontalDistance(b.location, hoverAt) shouldBeLessThan 0.2
        b.location.altitude.meters shouldBe ((ground + 20) plusOrMinus 0.1)
        b.onGround shouldBe false
    }

    "a multirotor flies to a waypoint no faster than its cruise speed and stops inside the acceptance radius" {
        val start = Body(atAltitude(HOME, ground + 20), onGround = false)
        val target = atAltitude(HOME.offset(north = 150.m, east = 80.m), ground + 30)
        var fastest = 0.0
        val b = fly(start, Guidance.GoTo(target), copter, 60.0, MultirotorAirframe) { fastest = maxOf(fastest, hypot(it.velocityNorth, it.velocityEast)) }
        horizontalDistance(b.location, target) shouldBeLessThan 2.0
        b.location.altitude.meters shouldBe ((ground + 30) plusOrMinus 0.5)
        fastest shouldBeLessThan 5.0 + 1e-6
        b.heading shouldBe (pod.sim.flight.bearing(HOME, target) plusOrMinus 2.0)
    }

    "a plane in the air never flies below its minimum airspeed and settles on its loiter circle" {
        val center = atAltitude(HOME.offset(north = 300.m, east = 0.m), ground + 100)
        var b = Body(atAltitude(HOME, ground + 80), airspeed = 15.0, onGround = false)
        b = fly(b, Guidance.Loiter(center, 60.0), plane, 120.0, FixedWingAirframe) { it.airspeed shouldBeGreaterThanOrEqual 9.0 }
        fly(b, Guidance.Loiter(center, 60.0), plane, 120.0, FixedWingAirframe) {
            horizontalDistance(it.location, center) shouldBe (60.0 plusOrMinus 8.0)
            it.airspeed shouldBeGreaterThanOrEqual 9.0
        }
    }

    "a plane's turn rate stays within what its bank limit allows" {
        var b = Body(atAltitude(HOME, ground + 80), airspeed = 15.0, onGround = false, heading = 0.0)
        val behind = HOME.offset(north = (-500).m, east = 0.m).let { atAltitude(it, ground + 80) }
        val maxRate = Math.toDegrees(9.80665 * kotlin.math.tan(Math.toRadians(45.0)) / 9.0)
        repeat(400) {
            val next = FixedWingAirframe.step(b, Guidance.GoTo(behind), plane, ground, true, DT)
            kotlin.math.abs(pod.sim.flight.turn(b.heading, next.heading)) / DT shouldBeLessThan maxRate + 1e-6
            b = next
        }
    }
})
