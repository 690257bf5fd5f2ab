package pod.sim.autopilot

import pod.mavlink.command.CommandResult
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.vehicle.LandedState
import pod.sim.flight.horizontalDistance

/**
 * The simulator has no transmitter: its throttle stick reads minimum, as SITL's RC3 = 1000 and a
 * vehicle flown only by a ground station. ArduCopter modes that take their climb rate from the
 * stick then descend; the modes a ground station holds in do not.
 */
class NoPilotInputTest : StringSpec({

    /** An ArduCopter hovering 20 m above home in GUIDED. */
    fun hovering(): SimAutopilot {
        val ap = autopilot()
        ap.run(2.5)
        ap.mode("GUIDED") shouldBe CommandResult.ACCEPTED
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(22, z = 20f)) shouldBe CommandResult.ACCEPTED
        ap.runUntil(30.0) { it.activity is Activity.Hold }
        ap.run(2.0)
        return ap
    }

    fun SimAutopilot.height() = body.location.altitude.meters - HOME.altitude.meters

    for (mode in listOf("LOITER", "POSHOLD", "ALT_HOLD")) {
        "ArduCopter $mode with the throttle stick at minimum descends at PILOT_SPEED_UP (PILOT_SPEED_DN 0), lands where it is and disarms" {
            val ap = hovering()
            val where = ap.body.location
            ap.mode(mode) shouldBe CommandResult.ACCEPTED
            var fastest = 0.0
            ap.runUntil(30.0, check = { fastest = maxOf(fastest, it.body.velocityDown) }) { it.body.onGround }
            fastest shouldBe (2.5 plusOrMinus 0.01) // PILOT_SPEED_UP default 250 cm/s
            horizontalDistance(ap.body.location, where) shouldBeLessThan 1.0
            ap.state().landedState shouldBe LandedState.ON_GROUND
            ap.modeName shouldBe mode
            // DISARM_DELAY (10 s) after touchdown, as the auto-disarm of a landed copter with its throttle at zero.
            ap.run(9.0)
            ap.armed shouldBe true
            ap.run(1.5)
            ap.armed shouldBe false
        }
    }

    "PILOT_SPEED_DN, when set, is the descent rate of LOITER with nobody on the sticks" {
        val ap = hovering()
        ap.params.set("PILOT_SPEED_DN", 100.0)
        ap.mode("LOITER")
        ap.run(5.0)
        ap.body.velocityDown shouldBe (1.0 plusOrMinus 0.01)
    }

    for (mode in listOf("BRAKE", "GUIDED")) {
        "ArduCopter $mode holds position and altitude with nobody on the sticks" {
            val ap = hovering()
            ap.mode("AUTO") // no mission: refused, stays in GUIDED
            val where = ap.body.location
            ap.mode(mode) shouldBe CommandResult.ACCEPTED
            ap.run(60.0) {
                it.height() shouldBe (20.0 plusOrMinus 0.3)
                horizontalDistance(it.body.location, where) shouldBeLessThan 1.0
            }
            ap.armed shouldBe true
        }
    }

    "ArduCopter STABILIZE with the throttle at minimum drops" {
        val ap = hovering()
        ap.mode("STABILIZE") shouldBe CommandResult.ACCEPTED
        ap.run(1.5)
        ap.body.velocityDown shouldBeGreaterThan 5.0
        ap.runUntil(10.0) { it.body.onGround }
    }

    "a user take-off in LOITER climbs to the take-off altitude, then the stick at minimum brings it down" {
        val ap = autopilot()
        ap.run(2.5)
        ap.mode("LOITER")
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(22, z = 10f)) shouldBe CommandResult.ACCEPTED
        ap.runUntil(20.0) { it.height() > 9.5 }
        ap.runUntil(20.0) { it.body.onGround }
    }
})
