package pod.sim.autopilot

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.command.CommandResult
import pod.mavlink.mission.MissionMessage
import pod.sim.flight.horizontalDistance
import kotlin.math.roundToLong

/** What the vehicle steers to ([pod.sim.SimState.target]) and ArduPilot's restart of a rewritten current item. */
class MissionRestartTest : StringSpec({

    fun SimAutopilot.target(): Location? = state().target

    fun near(a: Location?, b: Location): Boolean = a != null && horizontalDistance(a, b) < 0.5

    fun mission(second: Pair<Double, Double>) = listOf(
        homeItem(),
        item(22, alt = 20.0),
        item(16, 300.0, 0.0, 20.0),
        item(16, second.first, second.second, 20.0),
        item(16, 0.0, 300.0, 20.0),
    )

    /** An ArduCopter in AUTO flying item 2 of [mission] (north 300 m, then [second]). */
    fun flyingItem2(second: Pair<Double, Double>): SimAutopilot {
        val ap = autopilot()
        ap.load(mission(second))
        ap.run(2.5)
        ap.mode("GUIDED") shouldBe CommandResult.ACCEPTED
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(22, z = 20f)) shouldBe CommandResult.ACCEPTED
        ap.runUntil(60.0) { it.body.location.altitude.meters - HOME.altitude.meters > 19.8 }
        ap.onMissionMessage(MissionMessage.SetCurrent(2), 0)
        ap.mode("AUTO") shouldBe CommandResult.ACCEPTED
        ap.run(1.0)
        return ap
    }

    "the target is a guided go-to's point, the mission item being flown in AUTO, and nothing while hovering" {
        val ap = autopilot()
        ap.run(2.5)
        ap.mode("GUIDED")
        ap.armCommand()
        ap.command(CommandRequest(22, z = 10f))
        ap.runUntil(60.0) { it.body.location.altitude.meters - HOME.altitude.meters > 9.8 }
        ap.target().shouldBeNull()
        val point = HOME.offset(north = 80.m, east = 20.m)
        val lat = (point.latitude * 1e7).roundToLong().toDouble()
        val lon = (point.longitude * 1e7).roundToLong().toDouble()
        ap.command(CommandRequest(192, param1 = -1f, x = lat, y = lon, z = 10f, frame = 6)) shouldBe CommandResult.ACCEPTED
        near(ap.target(), point) shouldBe true

        val auto = flyingItem2(100.0 to 100.0)
        near(auto.target(), HOME.offset(north = 300.m, east = 0.m)) shouldBe true
    }

    "an ArduCopter keeps flying the old item after an upload rewrote it, and heads for the new one as soon as MISSION_SET_CURRENT names it" {
        val ap = flyingItem2(0.0 to 300.0)
        val old = HOME.offset(north = 300.m, east = 0.m)
        val new = HOME.offset(north = (-250).m, east = 50.m)
        ap.load(mission(0.0 to 300.0).toMutableList().also { it[2] = item(16, -250.0, 50.0, 20.0) })
        ap.run(1.0)
        near(ap.target(), old) shouldBe true // AP_Mission::replace_cmd: no effect until the command is restarted

        ap.onMissionMessage(MissionMessage.SetCurrent(2), 0).send.single() shouldBe MissionMessage.Current(2, 5)
        near(ap.target(), new) shouldBe true // in the handler, before any physics step
        ap.state().missionCurrent shouldBe 2
        val before = horizontalDistance(ap.body.location, new)
        ap.run(5.0)
        horizontalDistance(ap.body.location, new) shouldBeLessThan before - 5.0
    }

    "DO_SET_MISSION_CURRENT restarts the item the same way" {
        val ap = flyingItem2(0.0 to 300.0)
        val new = HOME.offset(north = 200.m, east = (-200).m)
        ap.load(mission(0.0 to 300.0).toMutableList().also { it[2] = item(16, 200.0, -200.0, 20.0) })
        ap.command(CommandRequest(224, param1 = 2f)) shouldBe CommandResult.ACCEPTED
        ap.target().shouldNotBeNull()
        near(ap.target(), new) shouldBe true
    }
})
