package pod.sim.autopilot

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.units.m
import pod.core.vehicle.VehicleType
import pod.mavlink.command.CommandResult
import pod.sim.flight.horizontalDistance

/**
 * ArduPilot's DO_REPOSITION outside a mission: ArduPlane in GUIDED circles the point at param3's
 * radius in param4's direction; ArduCopter ignores both and stops on the point. Directions are
 * read from the flown track's signed area (see [Track.signedArea]: clockwise positive).
 */
class GuidedCircleTest : StringSpec({

    /** An ArduPlane circling in LOITER at 50 m after its take-off. */
    fun planeInTheAir(): SimAutopilot = autopilot(type = VehicleType.FIXED_WING).also { ap ->
        ap.run(2.5)
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(22, z = 50f)) shouldBe CommandResult.ACCEPTED
        ap.runUntil(120.0) { it.modeName == "LOITER" }
    }

    val center = HOME.offset(north = 400.m, east = 300.m)

    "ArduPlane in GUIDED: a reposition with radius 120 m and param4 1 circles the point counter-clockwise at 120 m" {
        val ap = planeInTheAir()
        ap.mode("GUIDED") shouldBe CommandResult.ACCEPTED
        ap.command(repositionInt(center, 80.0, param3 = 120f, param4 = 1f)) shouldBe CommandResult.ACCEPTED
        ap.run(90.0) // there and onto the circle
        val track = ap.track(center, 120.0) // more than two laps at 15 m/s
        track.meanRadius shouldBe (120.0 plusOrMinus 18.0)
        track.signedArea shouldBeLessThan 0.0
        ap.body.location.altitude.meters - HOME.altitude.meters shouldBe (80.0 plusOrMinus 3.0)
    }

    "ArduPlane: param4 NaN or 0 with a radius circles clockwise" {
        for (p4 in listOf(Float.NaN, 0f)) {
            val ap = planeInTheAir()
            ap.command(repositionInt(center, 80.0, param2 = 1f, param3 = 120f, param4 = p4)) shouldBe CommandResult.ACCEPTED
            ap.modeName shouldBe "GUIDED"
            ap.run(90.0)
            val track = ap.track(center, 120.0)
            track.meanRadius shouldBe (120.0 plusOrMinus 18.0)
            track.signedArea shouldBeGreaterThan 0.0
        }
    }

    "ArduPlane: without param3 it circles at WP_LOITER_RAD, whose sign gives the direction unless param4 asks counter-clockwise" {
        val ap = planeInTheAir()
        ap.command(repositionInt(center, 80.0, param2 = 1f)) shouldBe CommandResult.ACCEPTED
        ap.run(90.0)
        val cw = ap.track(center, 60.0)
        cw.meanRadius shouldBe (60.0 plusOrMinus 9.0) // WP_LOITER_RAD's default
        cw.signedArea shouldBeGreaterThan 0.0

        ap.command(repositionInt(center, 80.0, param4 = 1f)) shouldBe CommandResult.ACCEPTED
        ap.run(60.0)
        ap.track(center, 60.0).signedArea shouldBeLessThan 0.0

        val negative = planeInTheAir()
        negative.params.set("WP_LOITER_RAD", -90.0)
        negative.command(repositionInt(center, 80.0, param2 = 1f)) shouldBe CommandResult.ACCEPTED
        negative.run(90.0)
        val ccw = negative.track(center, 80.0)
        ccw.meanRadius shouldBe (90.0 plusOrMinus 13.5)
        ccw.signedArea shouldBeLessThan 0.0
    }

    "ArduPlane keeps GUIDED's radius for later repositions until it leaves GUIDED" {
        val ap = planeInTheAir()
        ap.command(repositionInt(center, 80.0, param2 = 1f, param3 = 120f)) shouldBe CommandResult.ACCEPTED
        val next = HOME.offset(north = (-300).m, east = 200.m)
        ap.command(repositionInt(next, 80.0)) shouldBe CommandResult.ACCEPTED
        ap.run(120.0)
        ap.track(next, 60.0).meanRadius shouldBe (120.0 plusOrMinus 18.0)

        ap.mode("LOITER") shouldBe CommandResult.ACCEPTED
        ap.command(repositionInt(center, 80.0, param2 = 1f)) shouldBe CommandResult.ACCEPTED
        ap.run(120.0)
        ap.track(center, 60.0).meanRadius shouldBe (60.0 plusOrMinus 9.0)
    }

    "ArduPlane outside GUIDED without the change-mode flag answers FAILED and keeps loitering" {
        val ap = planeInTheAir()
        ap.command(repositionInt(center, 80.0, param3 = 120f)) shouldBe CommandResult.FAILED
        ap.modeName shouldBe "LOITER"
    }

    "ArduCopter ignores param3 and param4: it flies to the point and stops there" {
        val ap = autopilot()
        ap.run(2.5)
        ap.mode("GUIDED")
        ap.armCommand()
        ap.command(CommandRequest(22, z = 10f)) shouldBe CommandResult.ACCEPTED
        ap.run(8.0)
        val target = HOME.offset(north = 60.m, east = (-40).m)
        ap.command(repositionInt(target, 20.0, param3 = 50f, param4 = 1f)) shouldBe CommandResult.ACCEPTED
        ap.run(40.0)
        horizontalDistance(ap.body.location, target) shouldBeLessThan 0.5
        val stopped = ap.track(target, 20.0)
        stopped.radiusRange.endInclusive shouldBeLessThan 0.5
        stopped.meanSpeed shouldBeLessThan 0.05
    }

    "ArduCopter CIRCLE: CIRCLE_RADIUS around a point ahead, CIRCLE_RATE's sign the direction, at most √(½·WPNAV_ACCEL·r)" {
        for ((rate, clockwise) in listOf(20.0 to true, -20.0 to false)) {
            val ap = autopilot()
            ap.params.set("CIRCLE_RADIUS", 4000.0) // cm
            ap.params.set("CIRCLE_RATE", rate)
            ap.params.set("WPNAV_SPEED", 1500.0) // cm/s, so the acceleration limit is the one that binds
            ap.run(2.5)
            ap.mode("GUIDED")
            ap.armCommand()
            ap.command(CommandRequest(22, z = 10f)) shouldBe CommandResult.ACCEPTED
            ap.run(8.0)
            ap.mode("CIRCLE") shouldBe CommandResult.ACCEPTED
            val circle = ap.activity as Activity.Hold
            horizontalDistance(circle.center, ap.body.location) shouldBe (40.0 plusOrMinus 0.5)
            ap.run(30.0)
            val track = ap.track(circle.center, 60.0)
            track.meanRadius shouldBe (40.0 plusOrMinus 6.0)
            if (clockwise) track.signedArea shouldBeGreaterThan 0.0 else track.signedArea shouldBeLessThan 0.0
            track.meanSpeed shouldBe (kotlin.math.sqrt(0.5 * 2.5 * 40) plusOrMinus 0.5) // WPNAV_ACCEL 250 cm/s²
        }
    }
})
