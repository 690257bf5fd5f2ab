package pod.mavlink.plan

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.checkAll
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import pod.mavlink.mission.MissionItem
import kotlin.random.Random

private val otherFrames = listOf(MissionItem.FRAME_MISSION, 22, 255)
private val allFrames = (MissionItem.GLOBAL_FRAMES + MissionItem.LOCAL_FRAMES + otherFrames).toList()
private val specialFloats = listOf(Float.NaN, 0f, -0f, 0.1f, -1f, 1e-7f, Float.MIN_VALUE, Float.MAX_VALUE, 123456.79f, 1.5e20f)

private fun Random.param(): Float = if (nextInt(3) == 0) specialFloats.random(this) else (nextDouble(-1e4, 1e4)).toFloat()

private fun Random.item(seq: Int): MissionItem {
    val frame = allFrames.random(this)
    val global = frame in MissionItem.GLOBAL_FRAMES
    return MissionItem(
        seq = seq,
        frame = frame,
        command = nextInt(0, 65_536),
        autocontinue = nextBoolean(),
        param1 = param(), param2 = param(), param3 = param(), param4 = param(),
        x = if (global) nextInt(-900_000_000, 900_000_001) else nextInt(),
        y = if (global) nextInt(-1_800_000_000, 1_800_000_001) else nextInt(),
        z = param(),
    )
}

private fun Random.point() = PlanPoint(nextDouble(-90.0, 90.0), nextDouble(-180.0, 180.0))

private fun Random.position() =
    PlanPosition(nextDouble(-90.0, 90.0), nextDouble(-180.0, 180.0), if (nextInt(5) == 0) Double.NaN else nextDouble(-100.0, 5000.0))

private val plans: Arb<QgcPlan> = arbitrary { rs ->
    val r = rs.random
    val items = List(r.nextInt(0, 8)) { r.item(it) }
    QgcPlan(
        mission = items,
        geoFence = PlanGeoFence(
            polygons = List(r.nextInt(0, 3)) { FencePolygon(r.nextBoolean(), List(r.nextInt(3, 7)) { r.point() }) },
            circles = List(r.nextInt(0, 3)) { FenceCircle(r.nextBoolean(), r.point(), r.nextDouble(0.1, 1e5)) },
        ),
        rallyPoints = List(r.nextInt(0, 4)) { r.position() },
        plannedHome = if (r.nextBoolean()) r.position() else null,
        firmwareType = r.nextInt(0, 256),
        vehicleType = r.nextInt(0, 256),
        cruiseSpeed = if (r.nextBoolean()) r.nextDouble(0.0, 40.0) else null,
        hoverSpeed = if (r.nextBoolean()) r.nextDouble(0.0, 20.0) else null,
        groundStation = if (r.nextBoolean()) "QGroundControl" else "Pod",
        itemExtras = items.indices.filter { r.nextBoolean() }.associateWith {
            JsonObject(mapOf("Altitude" to JsonPrimitive(r.nextInt(0, 500)), "AltitudeMode" to JsonPrimitive(r.nextInt(0, 5))))
        },
        missionExtras = if (r.nextBoolean()) JsonObject(mapOf("globalPlanAltitudeMode" to JsonPrimitive(1))) else JsonObject(emptyMap()),
        extras = if (r.nextBoolean()) JsonObject(mapOf("x-pod-note" to JsonPrimitive("kept"))) else JsonObject(emptyMap()),
    )
}

private fun resource(name: String): String =
    (QgcPlanFileTest::class.java.getResource("/plans/$name") ?: error("missing resource /plans/$name")).readText()

private fun plan(body: String) = """{"fileType": "Plan", "version": 1, "groundStation": "QGroundControl", $body}"""

private fun failure(text: String): QgcPlanFormatException = shouldThrow<QgcPlanFormatException> { QgcPlanFile.read(text) }

class QgcPlanFileTest : StringSpec({
    // MissionItem is a data class: its Float fields compare with Float.compare, so NaN equals NaN and -0 ≠ 0.
    "random plans with NaN params, fences and rally points write and read back equal" {
        checkAll(PropTestConfig(seed = 16), plans) { plan ->
            val back = QgcPlanFile.read(QgcPlanFile.write(plan))
            back.copy(warnings = emptyList()) shouldBe plan
            // A warning for each item whose altitude QGC would compute from terrain, and only those.
            back.warnings.size shouldBe plan.mission.count { it.z.isNaN() && plan.itemExtras[it.seq]?.get("AltitudeMode") == JsonPrimitive(3) }
        }
    }

    "QGC's ArduCopter SITL plan loads with its frames, nulls and home, and writes back to the same plan" {
        val plan = QgcPlanFile.read(resource("ArduPilotSITL-ArduCopter.plan"))
        plan.mission.size shouldBe 11
        plan.mission.map { it.command } shouldBe listOf(22, 16, 178, 16, 201, 16, 19, 16, 82, 16, 21)
        plan.mission[0].x shouldBe -353_605_661
        plan.mission[0].y shouldBe 1_491_652_300
        plan.mission[0].param4.isNaN() shouldBe true
        plan.mission[2].frame shouldBe MissionItem.FRAME_MISSION
        listOf(plan.mission[2].param1, plan.mission[2].param2, plan.mission[2].param3) shouldBe listOf(1f, 10f, -1f)
        plan.mission[5].z.isNaN() shouldBe true
        plan.mission[7].frame shouldBe 10
        plan.plannedHome shouldBe PlanPosition(-35.363261, 149.16523, 584.0)
        plan.firmwareType shouldBe 3
        plan.vehicleType shouldBe 2
        plan.cruiseSpeed shouldBe 15.0
        plan.hoverSpeed shouldBe 5.0
        plan.itemExtras[3]?.get("AltitudeMode") shouldBe JsonPrimitive(2)
        plan.missionExtras["globalPlanAltitudeMode"] shouldBe JsonPrimitive(0)
        // Item 5's altitude is QGC's to calculate from terrain as it uploads: the file has none.
        plan.warnings shouldBe listOf(
            "mission.items[5]: altitude 80 m above terrain, which QGC calculates from its terrain data as it uploads " +
                "(AltitudeMode 3); the file holds no altitude for it, so it cannot be uploaded as it is",
        )
        QgcPlanFile.read(QgcPlanFile.write(plan)) shouldBe plan
    }

    "QGC's geofence plan loads an inclusion and an exclusion polygon and writes back to the same plan" {
        val plan = QgcPlanFile.read(resource("ce_geofence_home_base.plan"))
        plan.mission shouldBe emptyList()
        plan.geoFence.polygons.map { it.inclusion } shouldBe listOf(true, false)
        plan.geoFence.polygons[0].vertices[0] shouldBe PlanPoint(38.7507608625056, -77.49735908548331)
        plan.geoFence.polygons[1].vertices[3] shouldBe PlanPoint(38.7506564, -77.4972457)
        plan.geoFence.circles shouldBe emptyList()
        plan.plannedHome shouldBe PlanPosition(38.75084010396389, -77.49721463637287, 30.0)
        QgcPlanFile.read(QgcPlanFile.write(plan)) shouldBe plan
    }

    "a survey complex item reads as its expanded items with a warning" {
        val text = plan(
            """"mission": {"version": 2, "firmwareType": 12, "vehicleType": 2, "items": [
              {"type": "SimpleItem", "command": 22, "frame": 3, "autoContinue": true, "doJumpId": 1,
               "params": [0, 0, 0, null, 47.1, 8.1, 20]},
              {"type": "ComplexItem", "complexItemType": "survey", "version": 5, "polygon": [[47.1, 8.1], [47.2, 8.1], [47.2, 8.2]],
               "TransectStyleComplexItem": {"version": 2, "Items": [
                 {"type": "SimpleItem", "command": 16, "frame": 3, "autoContinue": true, "doJumpId": 2,
                  "params": [0, 0, 0, null, 47.11, 8.11, 50]},
                 {"type": "SimpleItem", "command": 206, "frame": 2, "autoContinue": true, "doJumpId": 3,
                  "params": [25, 0, 1, 0, 0, 0, 0]}]}}]},
            "geoFence": {"version": 2, "polygons": [], "circles": [{"circle": {"center": [47.15, 8.15], "radius": 400}, "inclusion": true, "version": 1}]},
            "rallyPoints": {"version": 2, "points": [[47.12, 8.12, 30]]}""",
        )
        val plan = QgcPlanFile.read(text)
        plan.mission.map { it.command } shouldBe listOf(22, 16, 206)
        plan.mission.map { it.seq } shouldBe listOf(0, 1, 2)
        plan.mission[1].x shouldBe 471_100_000
        plan.mission[2].param1 shouldBe 25f
        plan.warnings.size shouldBe 1
        plan.warnings[0] shouldContain "survey complex item read as its 2 expanded items"
        plan.geoFence.circles shouldBe listOf(FenceCircle(true, PlanPoint(47.15, 8.15), 400.0))
        plan.rallyPoints shouldBe listOf(PlanPosition(47.12, 8.12, 30.0))
        QgcPlanFile.read(QgcPlanFile.write(plan)) shouldBe plan.copy(warnings = emptyList())
    }

    "malformed plans fail with the path of the bad value" {
        failure("{ not json").path shouldBe ""
        failure("""{"fileType": "Mission", "version": 1, "mission": {}}""").reason shouldContain "fileType is 'Mission'"
        failure(plan(""""mission": {"version": 2}""")).path shouldBe "mission"
        failure(plan(""""mission": {"version": 2, "items": [{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0]}]}"""))
            .path shouldBe "mission.items[0].params"
        failure(plan(""""mission": {"version": 2, "items": [{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0, 0, 91, 8, 10]}]}"""))
            .path shouldBe "mission.items[0].params[4]"
        failure(plan(""""mission": {"version": 2, "items": [{"type": "SimpleItem", "command": "16", "frame": 3, "params": [0, 0, 0, 0, 1, 8, 10]}]}"""))
            .path shouldBe "mission.items[0].command"
        failure(plan(""""mission": {"version": 2, "items": [{"type": "ComplexItem", "complexItemType": "fwLandingPattern"}]}"""))
            .reason shouldContain "fwLandingPattern"
        failure(plan(""""mission": {"version": 2, "items": []}, "geoFence": {"polygons": [{"inclusion": true, "polygon": [[1, 2], [1, 200], [2, 2]]}]}"""))
            .path shouldBe "geoFence.polygons[0].polygon[1][1]"
        failure(plan(""""mission": {"version": 2, "items": [{"type": "SimpleItem", "command": 16, "frame": 3, "params": [1e99999, 0, 0, 0, 1, 8, 10]}]}"""))
            .path shouldBe "mission.items[0].params[0]"
    }

    "writing refuses an infinite param that JSON cannot hold" {
        shouldThrow<IllegalArgumentException> {
            QgcPlanFile.write(QgcPlan(mission = listOf(MissionItem(seq = 0, frame = 3, command = 16, param1 = Float.POSITIVE_INFINITY))))
        }.message shouldContain "infinity"
    }
})
