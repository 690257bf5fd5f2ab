package pod.sim.autopilot

import pod.mavlink.command.CommandResult
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainInOrder
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThanOrEqual
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.ints.shouldBeGreaterThanOrEqual
import io.kotest.matchers.shouldBe
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType
import pod.sim.flight.horizontalDistance

class MissionFlightTest : StringSpec({

    fun survey(): List<pod.mavlink.mission.MissionItem> = listOf(
        item(22, alt = 20.0),
        item(16, 100.0, 0.0, 20.0),
        item(16, 100.0, 100.0, 25.0),
        item(16, 0.0, 100.0, 25.0),
        item(16, -50.0, 50.0, 20.0),
        item(16, 50.0, -50.0, 20.0),
        item(18, 0.0, 0.0, 20.0, p1 = 2f, p3 = 15f),
        item(20, global = false),
    )

    "an ArduCopter flies take-off, five waypoints, two loiter turns and RTL in order and ends landed and disarmed at home" {
        val ap = autopilot()
        ap.load(listOf(homeItem()) + survey())
        // GUIDED needs a position (Copter::set_mode "requires position"): after boot's 2 s.
        ap.run(2.5)
        ap.mode("GUIDED") shouldBe CommandResult.ACCEPTED
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        ap.modeName shouldBe "AUTO"
        var highest = 0.0
        ap.runUntil(900.0, check = { highest = maxOf(highest, it.body.location.altitude.meters) }) { !it.armed && it.reached.size == 8 }
        ap.reached shouldBe (1..8).toList()
        ap.state().landedState shouldBe LandedState.ON_GROUND
        horizontalDistance(ap.body.location, HOME) shouldBeLessThan 2.0
        highest - HOME.altitude.meters shouldBe (25.0 plusOrMinus 0.5) // RTL_ALT 15 m is below where it already was
        ap.drain().filterIsInstance<SimOutput.ItemReached>().map { it.seq } shouldBe (1..8).toList()
    }

    "a PX4 multirotor started on the ground by MISSION_START arms itself, flies from item 0 and lands and disarms at home" {
        val ap = autopilot(Autopilot.PX4)
        ap.load(survey())
        ap.run(2.5)
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        ap.armed shouldBe true
        ap.modeName shouldBe "AUTO.MISSION"
        ap.runUntil(1500.0) { !it.armed && it.reached.size == 8 }
        ap.reached shouldBe (0..7).toList()
        ap.state().landedState shouldBe LandedState.ON_GROUND
        horizontalDistance(ap.body.location, HOME) shouldBeLessThan 2.0
    }

    "an ArduPlane takes off, flies its waypoints, follows DO_LAND_START to NAV_LAND, lands at the land point and disarms" {
        val ap = autopilot(type = VehicleType.FIXED_WING)
        ap.params.set("RTL_AUTOLAND", 2.0) // a mission holding DO_LAND_START arms only with RTL_AUTOLAND set
        ap.load(
            listOf(
                homeItem(),
                item(22, alt = 40.0),
                item(16, 500.0, 0.0, 60.0),
                item(16, 500.0, 500.0, 60.0),
                item(189, global = false),
                item(16, 0.0, 700.0, 30.0),
                item(21, 0.0, 150.0, 0.0),
            ),
        )
        ap.run(2.5)
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        var minAirspeedInAir = Double.MAX_VALUE
        ap.runUntil(900.0, check = { if (!it.body.onGround) minAirspeedInAir = minOf(minAirspeedInAir, it.body.airspeed) }) { !it.armed }
        ap.reached shouldBe listOf(1, 2, 3, 5, 6)
        minAirspeedInAir shouldBeGreaterThanOrEqual 9.0
        ap.state().landedState shouldBe LandedState.ON_GROUND
        horizontalDistance(ap.body.location, HOME.offset(north = pod.core.units.Distance(0.0), east = pod.core.units.Distance(150.0))) shouldBeLessThan 80.0
    }

    "an ArduPlane whose mission ends in the air returns home and circles it in RTL" {
        val ap = autopilot(type = VehicleType.FIXED_WING)
        ap.load(listOf(homeItem(), item(22, alt = 40.0), item(16, 600.0, 0.0, 60.0)))
        ap.run(2.5)
        ap.armCommand()
        ap.command(CommandRequest(300))
        ap.runUntil(300.0) { it.modeName == "RTL" }
        ap.run(200.0)
        horizontalDistance(ap.body.location, HOME) shouldBe (60.0 plusOrMinus 10.0)
        ap.body.location.altitude.meters - HOME.altitude.meters shouldBe (100.0 plusOrMinus 2.0) // ALT_HOLD_RTL 10000 cm
    }

    "DO_JUMP repeats its target items the given number of times" {
        val ap = autopilot()
        ap.load(
            listOf(
                homeItem(), item(22, alt = 10.0), item(16, 30.0, 0.0, 10.0), item(16, 30.0, 30.0, 10.0),
                item(177, p1 = 2f, p2 = 2f, global = false), item(16, 0.0, 0.0, 10.0), item(21, global = false),
            ),
        )
        ap.mode("GUIDED")
        ap.run(2.5)
        ap.armCommand()
        ap.command(CommandRequest(300))
        ap.runUntil(600.0) { !it.armed }
        // ArduCopter reports no final NAV_LAND reached (see ArduCopterMissionEndTest).
        ap.reached shouldBe listOf(1, 2, 3, 2, 3, 2, 3, 5)
    }

    "camera items take photos by distance, by interval and on demand, each recorded with where it was taken" {
        val ap = autopilot()
        ap.load(
            listOf(
                homeItem(), item(22, alt = 10.0),
                item(206, p1 = 20f, global = false),
                item(16, 100.0, 0.0, 10.0),
                item(206, p1 = 0f, global = false),
                item(2000, p2 = 2f, p3 = 3f, global = false),
                item(16, 100.0, 100.0, 10.0),
                item(203, global = false, x = 1),
                item(20, global = false),
            ),
        )
        ap.mode("GUIDED")
        ap.run(2.5)
        ap.armCommand()
        ap.command(CommandRequest(300))
        ap.runUntil(600.0) { !it.armed }
        val byDistance = ap.photos.filter { it.missionSeq == 3 }
        byDistance.size shouldBeGreaterThanOrEqual 5
        byDistance.zipWithNext { a, b -> horizontalDistance(a.location, b.location) shouldBeGreaterThanOrEqual 19.9 }
        val byInterval = ap.photos.filter { it.missionSeq == 6 }
        byInterval.size shouldBe 3
        byInterval.zipWithNext { a, b -> (b.time - a.time).inWholeMilliseconds.toDouble() shouldBe (2000.0 plusOrMinus 60.0) }
        ap.photos.size shouldBe byDistance.size + 3 + 1
        ap.photos.map { it.index } shouldBe ap.photos.indices.toList()
        ap.drain().filterIsInstance<SimOutput.Photo>().size shouldBe ap.photos.size
    }

    "an ArduCopter paused mid-leg holds position and altitude, then continues the same item" {
        val ap = autopilot()
        ap.load(listOf(homeItem(), item(22, alt = 20.0), item(16, 200.0, 0.0, 20.0), item(21, global = false)))
        ap.mode("GUIDED")
        ap.run(2.5)
        ap.armCommand()
        ap.command(CommandRequest(300))
        ap.runUntil(120.0) { it.missionServer.current == 2 && pod.sim.flight.northEast(HOME, it.body.location).first > 60 }
        ap.command(CommandRequest(193, param1 = 0f)) shouldBe CommandResult.ACCEPTED
        ap.run(10.0)
        val held = ap.body.location
        ap.run(20.0) {
            horizontalDistance(it.body.location, held) shouldBeLessThan 0.3
            it.body.location.altitude.meters - HOME.altitude.meters shouldBe (20.0 plusOrMinus 0.3)
            it.missionServer.current shouldBe 2
        }
        ap.command(CommandRequest(193, param1 = 1f)) shouldBe CommandResult.ACCEPTED
        ap.runUntil(300.0) { !it.armed }
        ap.reached shouldBe listOf(1, 2) // and the final NAV_LAND, which ArduCopter does not report reached
        horizontalDistance(ap.body.location, HOME.offset(north = pod.core.units.Distance(200.0), east = pod.core.units.Distance(0.0))) shouldBeLessThan 2.0
    }

    "MISSION_SET_CURRENT while flying AUTO makes the vehicle skip to that item" {
        val ap = autopilot()
        ap.load(listOf(homeItem(), item(22, alt = 10.0), item(16, 100.0, 0.0, 10.0), item(16, 0.0, 100.0, 10.0), item(21, global = false)))
        ap.mode("GUIDED")
        ap.run(2.5)
        ap.armCommand()
        ap.command(CommandRequest(300))
        ap.runUntil(60.0) { it.missionServer.current == 2 }
        ap.missionServer.onMessage(pod.mavlink.mission.MissionMessage.SetCurrent(3), 0)
        ap.runUntil(300.0) { !it.armed }
        ap.reached shouldContainInOrder listOf(1, 3) // then it lands on item 4, which ArduCopter does not report reached
        (2 in ap.reached) shouldBe false
    }
})
