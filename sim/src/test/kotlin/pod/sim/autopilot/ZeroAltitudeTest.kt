package pod.sim.autopilot

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.command.CommandResult
import pod.mavlink.mission.MissionItem
import pod.core.units.m
import pod.sim.flight.horizontalDistance

/**
 * A mission item at 0 m above home: ArduCopter flies it at its current altitude, ArduPlane only a
 * "loiter on the spot" (no latitude and longitude), PX4 never ([ItemAltitude]); the simulator ends
 * a flight that goes along the ground away from a take-off or a landing ("Crash: flew into terrain").
 */
class ZeroAltitudeTest : StringSpec({
    /**
     * Starts [items] (after ArduPilot's home item) in AUTO, armed, and flies until [done] or the
     * vehicle crashes; [lowest] is the lowest height above home once it has climbed past [cruise].
     */
    fun fly(ap: SimAutopilot, items: List<MissionItem>, texts: MutableList<String>, lowest: DoubleArray, cruise: Double = 29.0, done: (SimAutopilot) -> Boolean) {
        ap.run(2.5)
        ap.load(if ((ap.profile is pod.sim.autopilot.profile.Px4Profile)) items else listOf(homeItem()) + items)
        if (!(ap.profile is pod.sim.autopilot.profile.Px4Profile)) ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        var climbed = false
        ap.runUntil(600.0, check = {
            texts += it.drain().filterIsInstance<SimOutput.Text>().map { t -> t.text }
            val height = it.body.location.altitude.meters - HOME.altitude.meters
            if (height > cruise) climbed = true
            if (climbed) lowest[0] = minOf(lowest[0], height)
        }) { done(it) || it.crashed != null }
    }

    "ArduCopter flies a waypoint at 0 m at its current altitude (ModeAuto::loc_from_cmd)" {
        val ap = autopilot(Autopilot.ARDUPILOT)
        val texts = ArrayList<String>()
        val lowest = doubleArrayOf(Double.MAX_VALUE)
        fly(ap, listOf(item(22, alt = 30.0), item(16, 80.0, 0.0, 0.0), item(17, 80.0, 60.0, 0.0)), texts, lowest) {
            horizontalDistance(it.body.location, HOME.offset(north = 80.0.m, east = 60.0.m)) < 1.0
        }
        ap.crashed.shouldBeNull()
        lowest[0] shouldBeGreaterThan 29.0
    }

    "PX4 flies a waypoint at 0 m at ground level, and the simulator ends that flight in the terrain" {
        val ap = autopilot(Autopilot.PX4)
        val texts = ArrayList<String>()
        val lowest = doubleArrayOf(Double.MAX_VALUE)
        fly(ap, listOf(item(22, alt = 30.0), item(16, 300.0, 0.0, 0.0), item(16, 400.0, 0.0, 30.0)), texts, lowest) { it.reached.size >= 3 }
        ap.crashed shouldBe "flew into terrain"
        texts shouldContain "Crash: flew into terrain"
        ap.armed shouldBe false
        lowest[0] shouldBeLessThan 1.0
        // It went down on the way, well short of the waypoint: flying low was the failure, not arriving.
        horizontalDistance(ap.body.location, HOME) shouldBeLessThan 290.0
    }

    "ArduPlane flies a located waypoint at 0 m at ground level, but loiters on the spot at its altitude" {
        val plane = autopilot(type = VehicleType.FIXED_WING)
        fly(plane, listOf(item(22, alt = 40.0), item(16, 600.0, 0.0, 40.0), item(16, 1200.0, 0.0, 0.0)), ArrayList(), doubleArrayOf(Double.MAX_VALUE)) { it.reached.size >= 4 }
        plane.crashed shouldBe "flew into terrain"

        val onTheSpot = autopilot(type = VehicleType.FIXED_WING)
        val lowest = doubleArrayOf(Double.MAX_VALUE)
        fly(onTheSpot, listOf(item(22, alt = 40.0), item(16, 600.0, 0.0, 40.0), item(17, alt = 0.0, global = false)), ArrayList(), lowest, cruise = 37.0) { it.time > 150 }
        onTheSpot.crashed.shouldBeNull()
        lowest[0] shouldBeGreaterThan 30.0
    }

    "a copter landing at a point away from home is not a flight into terrain" {
        for (flavour in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
            val ap = autopilot(flavour)
            fly(ap, listOf(item(22, alt = 30.0), item(16, 80.0, 0.0, 30.0), item(21, 120.0, 40.0, 0.0)), ArrayList(), doubleArrayOf(Double.MAX_VALUE)) {
                it.body.onGround && !it.armed && it.time > 20
            }
            ap.crashed.shouldBeNull()
            horizontalDistance(ap.body.location, HOME.offset(north = 120.0.m, east = 40.0.m)) shouldBeLessThan 2.0
        }
    }
})
