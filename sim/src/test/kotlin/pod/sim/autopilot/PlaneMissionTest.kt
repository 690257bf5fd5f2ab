package pod.sim.autopilot

import pod.mavlink.command.CommandResult
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.vehicle.VehicleType
import pod.mavlink.mission.MissionMessage
import pod.mavlink.mission.MissionResult
import pod.mavlink.mission.MissionType
import pod.sim.flight.horizontalDistance

/** ArduPlane's arming checks, landings and mission handling as the simulator reproduces them. */
class PlaneMissionTest : StringSpec({

    fun plane(): SimAutopilot = autopilot(type = VehicleType.FIXED_WING).also { it.run(2.5) }

    fun SimAutopilot.texts(): List<String> = drain().filterIsInstance<SimOutput.Text>().map { it.text }

    /** Flies [items] from take-off to touchdown; returns where the plane stopped. */
    fun SimAutopilot.flyToTouchdown(items: List<pod.mavlink.mission.MissionItem>, texts: MutableList<String>) {
        load(listOf(homeItem()) + items)
        armCommand() shouldBe CommandResult.ACCEPTED
        command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        runUntil(900.0, check = { texts += it.texts() }) { it.body.onGround && it.body.airspeed < 0.1 && it.time > 30 }
    }

    "ArduPlane refuses to arm a mission holding DO_LAND_START while RTL_AUTOLAND is at its default 0" {
        val ap = plane()
        ap.load(listOf(homeItem(), item(22, alt = 40.0), item(189, global = false), item(21, 300.0, 0.0, 0.0)))
        val out = ArrayList<SimOutput>()
        ap.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.FAILED
        out.filterIsInstance<SimOutput.Text>().map { it.text } shouldContain "Arm: DO_LAND_START set and RTL_AUTOLAND disabled"
        ap.params.set("RTL_AUTOLAND", 2.0)
        ap.armCommand() shouldBe CommandResult.ACCEPTED
    }

    "ArduPlane arms a mission that lands without DO_LAND_START" {
        val ap = plane()
        ap.load(listOf(homeItem(), item(22, alt = 40.0), item(16, -350.0, 0.0, 30.0), item(21, 0.0, 0.0, 0.0)))
        ap.armCommand() shouldBe CommandResult.ACCEPTED
    }

    "an ArduPlane landing from a waypoint straight over the land point glides steeply, flares high and touches down far past it" {
        val ap = plane()
        val texts = ArrayList<String>()
        ap.flyToTouchdown(listOf(item(22, alt = 40.0), item(16, 600.0, 0.0, 40.0), item(16, 0.0, 0.0, 40.0), item(21, 0.0, 0.0, 0.0)), texts)
        val slope = texts.first { it.startsWith("Landing glide slope") }.removePrefix("Landing glide slope ").removeSuffix(" degrees").toDouble()
        slope shouldBeGreaterThan 30.0
        val flare = texts.first { it.startsWith("Flare ") }.removePrefix("Flare ").substringBefore("m").toDouble()
        flare shouldBeGreaterThan 6.0 // twice LAND_FLARE_ALT: early, from the sink rate (real ArduPlane, diving: 52 m)
        horizontalDistance(ap.body.location, HOME) shouldBeGreaterThan 150.0
    }

    "an ArduPlane landing from an approach waypoint 350 m out at 30 m glides at about 5° and touches down near the land point" {
        val ap = plane()
        val texts = ArrayList<String>()
        ap.flyToTouchdown(listOf(item(22, alt = 40.0), item(16, 600.0, 0.0, 40.0), item(16, -350.0, 0.0, 30.0), item(21, 0.0, 0.0, 0.0)), texts)
        val slope = texts.first { it.startsWith("Landing glide slope") }.removePrefix("Landing glide slope ").removeSuffix(" degrees").toDouble()
        slope shouldBeLessThan 6.0
        val flare = texts.first { it.startsWith("Flare ") }.removePrefix("Flare ").substringBefore("m").toDouble()
        flare shouldBeLessThan 4.0
        horizontalDistance(ap.body.location, HOME) shouldBeLessThan 60.0
    }

    "clearing the mission of an ArduPlane sitting in AUTO switches it to RTL, in which it will not arm" {
        val ap = plane()
        ap.load(listOf(homeItem(), item(22, alt = 40.0), item(16, 600.0, 0.0, 40.0)))
        ap.mode("AUTO") shouldBe CommandResult.ACCEPTED
        ap.missionServer.onMessage(MissionMessage.ClearAll(MissionType.MISSION), 0).send shouldBe listOf(MissionMessage.Ack(MissionType.MISSION, MissionResult.ACCEPTED))
        ap.drain()
        ap.step(DT)
        ap.modeName shouldBe "RTL"
        ap.texts() shouldContain "Aircraft in auto without a running mission"
        val out = ArrayList<SimOutput>()
        ap.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.FAILED
        out.filterIsInstance<SimOutput.Text>().map { it.text } shouldContain "Arm: RTL mode not armable"
        ap.mode("MANUAL") shouldBe CommandResult.ACCEPTED
        ap.armCommand() shouldBe CommandResult.ACCEPTED
    }

    "ArduPilot refuses MISSION_CLEAR_ALL while armed and flying the mission in AUTO, and accepts it once out of AUTO" {
        val ap = plane()
        ap.load(listOf(homeItem(), item(22, alt = 40.0), item(16, 600.0, 0.0, 40.0), item(16, 600.0, 600.0, 40.0)))
        ap.armCommand()
        ap.command(CommandRequest(300))
        ap.runUntil(120.0) { it.body.location.altitude.meters > HOME.altitude.meters + 30.0 }
        val clear = MissionMessage.ClearAll(MissionType.MISSION)
        ap.missionServer.onMessage(clear, 0).send shouldBe listOf(MissionMessage.Ack(MissionType.MISSION, MissionResult.ERROR))
        ap.missionServer.list(MissionType.MISSION).size shouldBe 4
        ap.mode("LOITER") shouldBe CommandResult.ACCEPTED
        ap.missionServer.onMessage(clear, 0).send shouldBe listOf(MissionMessage.Ack(MissionType.MISSION, MissionResult.ACCEPTED))
        (ap.body.location.altitude.meters - HOME.altitude.meters) shouldBeGreaterThan 30.0
    }
})
