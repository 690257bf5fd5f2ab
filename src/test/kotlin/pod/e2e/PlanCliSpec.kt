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
import pod.mavlink.mission.ArduPilotMissionStorage
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
import kotlinx.serialization.json.JsonPrimitive
import java.io.File
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
                // What the vehicle tells of itself: autopilot, airframe, home (HOME_POSITION) and its default speed (MPC_XY_CRUISE).
                (back.firmwareType to back.vehicleType) shouldBe (12 to 2)
                back.hoverSpeed shouldBe 5.0
                back.cruiseSpeed shouldBe null
                val home = SimVehicleConfig.DEFAULT_HOME
                back.plannedHome shouldBe PlanPosition(home.latitude, home.longitude, home.altitude.meters)
            } finally {
                sim.stop()
                dir.toFile().deleteRecursively()
            }
        }
    }

    // QGC's own plan files (mavlink/src/test/resources/plans, sources in its README) through a vehicle and back.
    for ((name, autopilot) in listOf("ArduPilotSITL-ArduCopter.plan" to Autopilot.ARDUPILOT, "ce_geofence_home_base.plan" to Autopilot.PX4)) {
        "QGC's $name loads, uploads to a simulated $autopilot vehicle and downloads equal to what the autopilot keeps" {
            val file = generateSequence(File(System.getProperty("user.dir")).absoluteFile) { it.parentFile }
                .map { File(it, "mavlink/src/test/resources/plans/$name") }.first { it.isFile }
            val read = QgcPlanFile.read(file.toPath())
            coroutineScope {
                val port = freePort()
                val sim = SimVehicle(SimVehicleConfig(systemId = 17, autopilot = autopilot, gcs = "udpout://127.0.0.1:$port"))
                val dir = Files.createTempDirectory("pod-qgc-plan")
                try {
                    sim.start(this)
                    val connect = listOf("--connect", "udpin:127.0.0.1:$port", "--json")
                    val terrainItems = read.mission.filter { it.z.isNaN() && read.itemExtras[it.seq]?.get("AltitudeMode") == JsonPrimitive(3) }
                    val plan = if (terrainItems.isEmpty()) {
                        read
                    } else {
                        // As it is, the file names the items QGC would fill from terrain data, and nothing is sent.
                        val out = Captured()
                        val refused = shouldThrow<CliktError> { withContext(Dispatchers.IO) { Pod(out).parse(listOf("mission", "upload", file.path) + connect) } }
                        refused.statusCode shouldBe 2
                        refused.message!! shouldContain "item ${terrainItems[0].seq}"
                        out.events.filterIsInstance<Event.Warning>().single().message shouldContain "AltitudeMode 3"
                        sim.missionServer.list(MissionType.MISSION) shouldBe emptyList()
                        // What QGC sends over flat ground at the planned home's elevation: 80 m above it, AMSL.
                        val ground = read.plannedHome!!.altitude.toFloat()
                        read.copy(mission = read.mission.map { if (it in terrainItems) it.copy(z = ground + 80f) else it }, warnings = emptyList())
                    }
                    val upload = dir.resolve("upload.plan").also { QgcPlanFile.write(it, plan) }
                    withContext(Dispatchers.IO) { Pod(Captured()).parse(listOf("mission", "upload", upload.toString()) + connect) }
                    val download = dir.resolve("back.plan")
                    withContext(Dispatchers.IO) { Pod(Captured()).parse(listOf("mission", "download", download.toString()) + connect) }
                    val back = QgcPlanFile.read(download)
                    // ArduPilot normalises what it stores (unused params and NaNs to 0, a DO_ command's
                    // frame to 0), and keeps its home in item 0, ahead of the plan's items, as QGC sends them.
                    // A yaw ArduPilot does not store is written as unknown (null), not as the 0 it sends back.
                    val kept = if (autopilot == Autopilot.ARDUPILOT) {
                        ArduPilotMissionStorage.stored(plan.mission, fixedWing = false).map { if (it.command in setOf(16, 22) && it.param4 == 0f) it.copy(param4 = Float.NaN) else it }
                    } else {
                        plan.mission
                    }
                    back.mission shouldBe kept
                    if (autopilot == Autopilot.ARDUPILOT) {
                        sim.missionServer.list(MissionType.MISSION).map { it.command } shouldBe listOf(16) + plan.mission.map { it.command }
                        // What comes back as the planned home is the vehicle's, which ArduPilot writes over item 0.
                        val home = SimVehicleConfig.DEFAULT_HOME
                        back.plannedHome!!.let { listOf(it.latitude, it.longitude, it.altitude) } shouldBe listOf(home.latitude, home.longitude, home.altitude.meters)
                    } else {
                        // PX4 keeps no home in its mission: the planned home is its HOME_POSITION.
                        val home = SimVehicleConfig.DEFAULT_HOME
                        back.plannedHome shouldBe PlanPosition(home.latitude, home.longitude, home.altitude.meters)
                    }
                    // Fence and rally travel as degrees × 10⁷: the plan's vertices come back rounded to that.
                    back.geoFence shouldBe PlanLists.fence(PlanLists.fenceItems(plan.geoFence))
                    back.rallyPoints shouldBe PlanLists.rallyPoints(PlanLists.rallyItems(plan.rallyPoints))
                    sim.missionServer.list(MissionType.FENCE).size shouldBe plan.geoFence.polygons.sumOf { it.vertices.size } + plan.geoFence.circles.size
                } finally {
                    sim.stop()
                    dir.toFile().deleteRecursively()
                }
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
