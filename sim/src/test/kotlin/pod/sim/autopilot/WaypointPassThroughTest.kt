package pod.sim.autopilot

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.mavlink.command.CommandResult
import pod.core.vehicle.Autopilot
import pod.core.units.m
import pod.sim.flight.horizontalDistance
import kotlin.math.hypot

/**
 * A multirotor in a mission flies through a waypoint with no hold time when another waypoint
 * follows (ArduCopter's ModeAuto::set_next_wp, PX4's speed at target), and stops on one with a
 * hold time (param1), the last one, or at a corner slows down.
 */
class WaypointPassThroughTest : StringSpec({

    /** Take-off to 30 m, then [points] (north, east) at 30 m, each with hold time [hold]. */
    fun line(px4: Boolean, hold: Float, vararg points: Pair<Double, Double>) =
        (if (px4) emptyList() else listOf(homeItem(), item(22, alt = 30.0))) +
            (if (px4) listOf(item(22, alt = 30.0)) else emptyList()) +
            points.map { (n, e) -> item(16, n, e, 30.0, p1 = hold) }

    /** Flies [items] in AUTO and returns the lowest ground speed seen within [within] metres of (north, east). */
    fun slowestNear(flavour: Autopilot, items: List<pod.mavlink.mission.MissionItem>, north: Double, east: Double, reachedItems: Int, within: Double = 3.0): Double {
        val ap = autopilot(flavour)
        ap.load(items)
        ap.run(2.5)
        if (flavour == Autopilot.PX4) {
            ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        } else {
            ap.armCommand() shouldBe CommandResult.ACCEPTED
            ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        }
        val point = HOME.offset(north = north.m, east = east.m)
        var slowest = Double.MAX_VALUE
        ap.runUntil(300.0, check = {
            if (it.body.location.altitude.meters > HOME.altitude.meters + 25 && horizontalDistance(it.body.location, point) < within) {
                slowest = minOf(slowest, hypot(it.body.velocityNorth, it.body.velocityEast))
            }
        }) { it.reached.size >= reachedItems }
        return slowest
    }

    for (flavour in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
        val px4 = flavour == Autopilot.PX4
        val cruise = 5.0 // WPNAV_SPEED 500 cm/s, MPC_XY_CRUISE 5 m/s

        "$flavour: a copter flies through a waypoint without hold time on a straight line at cruise speed" {
            slowestNear(flavour, line(px4, 0f, 40.0 to 0.0, 80.0 to 0.0, 120.0 to 0.0), 80.0, 0.0, if (px4) 3 else 4) shouldBeGreaterThan 0.9 * cruise
        }

        // PX4 counts the hold from inside NAV_ACC_RAD (10 m), still braking (MissionBlock::is_mission_item_reached_or_completed).
        "$flavour: a copter stops on a waypoint with a hold time" {
            slowestNear(flavour, line(px4, 5f, 40.0 to 0.0, 80.0 to 0.0, 120.0 to 0.0), 80.0, 0.0, if (px4) 3 else 4) shouldBeLessThan 0.3
        }

        "$flavour: a copter slows down for a right-angle corner but does not stop" {
            // PX4 turns on to the next leg inside NAV_ACC_RAD (10 m), so it passes the corner point farther off.
            val slowest = slowestNear(flavour, line(px4, 0f, 40.0 to 0.0, 80.0 to 0.0, 80.0 to 40.0), 80.0, 0.0, if (px4) 3 else 4, within = if (px4) 12.0 else 3.0)
            slowest shouldBeLessThan 0.9 * cruise
            slowest shouldBeGreaterThan 0.5
        }
    }
})
