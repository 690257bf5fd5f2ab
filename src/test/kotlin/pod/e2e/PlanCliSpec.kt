package pod.e2e

import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.parse
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.withContext
import pod.cli.Pod
import pod.cli.json.Event
import pod.core.vehicle.Autopilot
import pod.mavlink.mission.MissionType
import pod.mavlink.plan.FenceCircle
import pod.mavlink.plan.FencePolygon
import pod.mavlink.plan.PlanGeoFence
import pod.mavlink.plan.PlanLists
import pod.mavlink.plan.PlanPoint
import pod.mavlink.plan.PlanPosition
import pod.mavlink.plan.QgcPlan
import pod.mavlink.plan.QgcPlanFile
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.nio.file.Files
import kotlin.io.path.writeText

/** A plan with every list filled; coordinates with at most 7 decimals, so the wire's 1e-7° rounding keeps them. */
private val fullPlan = QgcPlan(
    mission = waypoints(12).map { it.copy(current = false) }, // a .plan file has no "current" field
    geoFence = PlanGeoFence(
        polygons = listOf(
            FencePolygon(true, listOf(PlanPoint(41.1, -8.61), PlanPoint(41.11, -8.61), PlanPoint(41.11, -8.59), PlanPoint(41.1, -8.59))),
            FencePolygon(false, listOf(PlanPoint(41.104, -8.604), PlanPoint(41.1045, -8.604), PlanPoint(41.1045, -8.6035))),
        ),
        circles = listOf(FenceCircle(false, PlanPoint(41.106, -8.595), 40.0)),
    ),
    rallyPoints = listOf(PlanPosition(41.1012345, -8.6054321, 25.0), PlanPosition(41.108, -8.592, 40.0)),
    firmwareType = 12,
    vehicleType = 2,
)

class PlanCliSpec : StringSpec({
    "pod mission upload FILE.plan sends mission, fence and rally; download FILE.plan writes all three back equal" {
        coroutineScope {
            val port = freePort()
            val sim = SimVehicle(SimVehicleConfig(systemId = 16, autopilot = Autopilot.PX4, gcs = "udpout://127.0.0.1:$port"))
            val dir = Files.createTempDirectory("pod-plan-cli")
            try {
                sim.start(this)
                val upload = dir.resolve("survey.plan").also { QgcPlanFile.write(it, fullPlan) }
                val connect = listOf("--connect", "udpin:127.0.0.1:$port", "--json")
                val out = Captured()
                withContext(Dispatchers.IO) { Pod(out).parse(listOf("mission", "upload", upload.toString()) + connect) }
                val done = out.events.last().shouldBeInstanceOf<Event.Done>()
                (done.action to done.items) shouldBe ("upload" to 12 + 7 + 1 + 2)
                sim.missionServer.list(MissionType.MISSION) shouldBe fullPlan.mission
                sim.missionServer.list(MissionType.FENCE) shouldBe PlanLists.fenceItems(fullPlan.geoFence)
                sim.missionServer.list(MissionType.RALLY) shouldBe PlanLists.rallyItems(fullPlan.rallyPoints)

                val download = dir.resolve("back.plan")
                withContext(Dispatchers.IO) { Pod(Captured()).parse(listOf("mission", "download", download.toString()) + connect) }
                val back = QgcPlanFile.read(download)
                back.mission shouldBe fullPlan.mission
                back.geoFence shouldBe fullPlan.geoFence
                back.rallyPoints shouldBe fullPlan.rallyPoints
            } finally {
                sim.stop()
                dir.toFile().deleteRecursively()
            }
        }
    }

    "a malformed .plan file fails with the JSON path of the bad value and exit code 2, before any vehicle is asked" {
        val file = Files.createTempFile("pod-bad", ".plan")
        try {
            file.writeText("""{"fileType": "Plan", "version": 1, "mission": {"version": 2, "items": [{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0, 0, 95, 8, 10]}]}}""")
            val error = shouldThrow<CliktError> {
                withContext(Dispatchers.IO) { Pod(Lines()).parse(listOf("mission", "upload", file.toString(), "--connect", "udpin:127.0.0.1:${freePort()}")) }
            }
            error.statusCode shouldBe 2
            error.message!! shouldContain "mission.items[0].params[4]"
        } finally {
            Files.deleteIfExists(file)
        }
    }
})
