package pod.sim.autopilot

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.mavlink.command.CommandResult
import pod.sim.flight.northEast

/**
 * A copter told to hold while flying fast stops where its braking takes it and stays there: it
 * never flies back to where it was when told. ArduCopter BRAKE stops at 7.5 m/s²
 * (BRAKE_MODE_DECEL_RATE); PX4 Hold at its braking position.
 */
class BrakeStopTest : StringSpec({
    /** Flies a mission north at [speed] m/s, switches to [hold] at 100 m north; returns (stop past the switch, farthest back after it), metres. */
    fun brake(flavour: Autopilot, hold: String, speed: Double): Pair<Double, Double> {
        val ap = autopilot(flavour)
        if (flavour == Autopilot.PX4) ap.params.set("MPC_XY_CRUISE", speed) else ap.params.set("WPNAV_SPEED", speed * 100)
        ap.run(2.5)
        val px4 = flavour == Autopilot.PX4
        ap.load((if (px4) emptyList() else listOf(homeItem())) + listOf(item(22, alt = 30.0), item(16, 400.0, 0.0, 30.0)))
        if (!px4) ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        ap.runUntil(120.0) { northEast(HOME, it.body.location).first > 100.0 }
        kotlin.math.hypot(ap.body.velocityNorth, ap.body.velocityEast) shouldBe (speed plusOrMinus speed * 0.05)
        val switchedAt = northEast(HOME, ap.body.location).first
        ap.mode(hold) shouldBe CommandResult.ACCEPTED
        var farthest = switchedAt
        var backFrom = 0.0
        ap.run(40.0, check = {
            val north = northEast(HOME, it.body.location).first
            farthest = maxOf(farthest, north)
            backFrom = maxOf(backFrom, farthest - north)
        })
        return (farthest - switchedAt) to backFrom
    }

    "ArduCopter BRAKE from 10 m/s stops within its braking distance and holds there" {
        val (stop, back) = brake(Autopilot.ARDUPILOT, "BRAKE", 10.0)
        stop shouldBeLessThan 10.0 // 10²/(2·7.5) = 6.7 m, plus a step of reaction
        back shouldBeLessThan 0.5
    }

    "PX4 Hold from 10 m/s stops at its braking point and does not fly back" {
        val (stop, back) = brake(Autopilot.PX4, "AUTO.LOITER", 10.0)
        stop shouldBeLessThan 20.0 // 10²/(2·3) = 16.7 m (MPC_ACC_HOR 3 m/s²)
        back shouldBeLessThan 0.5
    }
})
