package pod.sim.autopilot

import pod.mavlink.command.CommandResult
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.shouldBe
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType

/** How missions end on the simulated ArduCopter, as on the real one (see MissionRunner.touchedDown). */
class ArduCopterMissionEndTest : StringSpec({

    fun flown(ap: SimAutopilot, vararg items: pod.mavlink.mission.MissionItem): MutableList<SimOutput> {
        ap.load(listOf(homeItem()) + items)
        ap.mode("GUIDED")
        ap.run(2.5)
        ap.armCommand()
        ap.command(CommandRequest(300))
        ap.drain()
        val outputs = ArrayList<SimOutput>()
        ap.runUntil(300.0, check = { outputs += it.drain() }) { !it.armed }
        ap.run(2.0) { outputs += it.drain() }
        return outputs
    }

    "a mission ending in NAV_LAND: disarmed on touchdown, no MISSION_ITEM_REACHED for the land, current back to item 1, still in AUTO" {
        val ap = autopilot()
        val outputs = flown(ap, item(22, alt = 10.0), item(16, 40.0, 0.0, 10.0), item(21, 40.0, 0.0, 0.0))
        outputs.filterIsInstance<SimOutput.ItemReached>().map { it.seq } shouldBe listOf(1, 2)
        ap.state().landedState shouldBe LandedState.ON_GROUND
        ap.missionServer.current shouldBe 1
        ap.modeName shouldBe "AUTO"
        outputs.filterIsInstance<SimOutput.Text>().map { it.text } shouldContain "Mission: 1 Takeoff"
        // ArduPilot sends MISSION_CURRENT when asked (a stream, MISSION_SET_CURRENT), not on each change.
        outputs.filterIsInstance<SimOutput.MissionCurrent>().shouldBeEmpty()
    }

    "a landing followed by a take-off is reached like any item, and the mission goes on" {
        val ap = autopilot()
        ap.load(listOf(homeItem(), item(22, alt = 10.0), item(21, 30.0, 0.0, 0.0), item(22, alt = 10.0), item(21, global = false)))
        ap.mode("GUIDED")
        ap.run(2.5)
        ap.armCommand()
        ap.command(CommandRequest(300))
        ap.runUntil(200.0) { 2 in it.reached }
        ap.runUntil(200.0) { 3 in it.reached }
        ap.reached shouldBe listOf(1, 2, 3)
    }

    "PX4 still reports its final land reached and announces each new current item" {
        val ap = autopilot(Autopilot.PX4, VehicleType.QUADROTOR)
        ap.load(listOf(item(22, alt = 10.0), item(16, 40.0, 0.0, 10.0), item(21, 40.0, 0.0, 0.0)))
        ap.run(2.5)
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        val outputs = ArrayList<SimOutput>()
        ap.runUntil(300.0, check = { outputs += it.drain() }) { it.reached.size == 3 }
        outputs.filterIsInstance<SimOutput.ItemReached>().map { it.seq } shouldBe listOf(0, 1, 2)
        outputs.filterIsInstance<SimOutput.MissionCurrent>().map { it.seq } shouldContain 2
    }
})
