package pod.cli.gcs

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import pod.cli.json.OnBoardItem
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.mission.WplFile
import pod.mavlink.plan.PlanOnVehicle
import pod.mavlink.plan.PlanPosition
import pod.mavlink.plan.QgcPlan
import pod.mavlink.plan.QgcPlanFile

private fun waypoint(seq: Int, command: Int = 16, lat: Double? = 41.1 + seq / 1000.0) = MissionItem(
    seq = seq, frame = 3, command = command,
    x = lat?.let { Math.round(it * 1e7).toInt() } ?: 0, y = lat?.let { -86_000_000 } ?: 0, z = 30f,
)

private val plan = QgcPlan(
    mission = listOf(waypoint(0, command = 22, lat = null), waypoint(1), waypoint(2, command = 201), waypoint(3)),
    plannedHome = PlanPosition(41.1, -8.6, 120.0),
)

class PlanFileTest : StringSpec({

    "a .plan's lists go to each autopilot numbered as QGC numbers them; an empty one is refused before anything is sent" {
        val file = PlanFile.read("/home/op/Downloads/survey.plan", QgcPlanFile.write(plan))
        file.name shouldBe "survey.plan"
        file.lists(Autopilot.PX4).map { it.first } shouldBe listOf(MissionType.MISSION, MissionType.FENCE, MissionType.RALLY)
        file.lists(Autopilot.PX4)[0].second shouldBe plan.mission
        // ArduPilot: the planned home as item 0, the plan's items from 1.
        file.lists(Autopilot.ARDUPILOT)[0].second shouldBe PlanOnVehicle.missionItems(plan, Autopilot.ARDUPILOT)
        file.lists(Autopilot.ARDUPILOT)[0].second.size shouldBe 5

        val empty = PlanFile.read("empty.plan", QgcPlanFile.write(QgcPlan()))
        shouldThrow<GcsRequestException> { empty.lists(Autopilot.PX4) }.message shouldBe
            "empty.plan holds no items: uploading it would clear the vehicle's lists"
    }

    "every unreadable file is refused with its name first, then what is wrong and where" {
        fun refusal(name: String, text: String) = shouldThrow<GcsRequestException> { PlanFile.read(name, text) }.message!!
        refusal("a.plan", "{ not json") shouldStartWith "a.plan: plan: not JSON"
        refusal("b.plan", """{"fileType": "Plan", "version": 1, "mission": {"version": 2, "items": [{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0, 0, 95, 8, 10]}]}}""") shouldStartWith
            "b.plan: plan mission.items[0].params[4]"
        refusal("c.waypoints", "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\tnorth\t-8.6\t0\t1\n") shouldStartWith "c.waypoints: WPL line 2:"
        refusal("photo.jpg", "\u00ff\u00d8") shouldBe
            "photo.jpg: not a plan file: the page takes QGC .plan files and QGC WPL 110 files (.waypoints, .txt, .mission)"
        refusal("huge.plan", " ".repeat(PlanFile.MAX_CHARS + 1)) shouldStartWith "huge.plan is too large for a plan file"
    }

    "a WPL mission's line 0 is home: kept for ArduPilot, left out for PX4; a fence file goes as it is" {
        val lines = listOf(waypoint(0).copy(frame = 0, current = true), waypoint(1), waypoint(2))
        val file = PlanFile.read("route.waypoints", WplFile.write(lines))
        file.lists(Autopilot.ARDUPILOT).single().second.map { it.seq } shouldBe listOf(0, 1, 2)
        file.lists(Autopilot.PX4).single().second.map { it.x } shouldBe lines.drop(1).map { it.x }
        val fence = PlanFile.read("zone.txt", WplFile.write(lines), MissionType.FENCE)
        // A WPL file read as a fence list must hold fence commands: checked as the vehicle would.
        shouldThrow<GcsRequestException> { fence.lists(Autopilot.PX4) }.message!! shouldStartWith "zone.txt (fence list): invalid fence item 0"
    }

    "the map numbers a mission's positioned items from 1 after ArduPilot's home, and joins only navigation commands" {
        val ardupilot = PlanOnVehicle.missionItems(plan, Autopilot.ARDUPILOT)
        val back = PlanOnVehicle.plan(ardupilot, emptyList(), emptyList(), Autopilot.ARDUPILOT)
        val shown = OnBoardShapes.of(1, back, ardupilot)
        // The takeoff has no position (the vehicle's own): counted, not drawn.
        shown.mission.map { listOf(it.seq, it.n, it.nav) } shouldBe listOf(listOf(2, 2, true), listOf(3, 3, false), listOf(4, 4, true))
        shown.missionItems shouldBe 4
        shown.home shouldBe listOf(41.1, -8.6)
        val px4 = OnBoardShapes.of(2, plan, plan.mission)
        px4.mission.first() shouldBe OnBoardItem(seq = 1, n = 2, command = 16, lat = 41.101, lon = -8.6, alt = 30.0, nav = true)
    }
})
