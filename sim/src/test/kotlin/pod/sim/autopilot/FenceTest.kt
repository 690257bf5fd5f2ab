package pod.sim.autopilot

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.collections.shouldNotContain
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.Severity
import pod.core.vehicle.VehicleType
import pod.mavlink.command.CommandResult
import pod.mavlink.mission.MissionType
import pod.mavlink.plan.FenceCircle
import pod.mavlink.plan.FencePolygon
import pod.mavlink.plan.PlanGeoFence
import pod.mavlink.plan.PlanLists
import pod.mavlink.plan.PlanPoint
import pod.mavlink.telemetry.FlightModes
import pod.sim.flight.horizontalDistance
import pod.sim.flight.northEast
import kotlin.math.roundToLong

/**
 * Fences uploaded to a simulated vehicle are enforced as ArduPilot 4.7 and PX4 enforce them (see
 * ArduPilotFence and Px4Geofence for the sources): the breach is announced, the fence action's
 * mode taken once, and the vehicle does not fly on past the edge.
 */
class FenceTest : StringSpec({

    fun point(north: Double, east: Double) = HOME.offset(north = north.m, east = east.m).let { PlanPoint(it.latitude, it.longitude) }

    /** A square zone [half] metres either side of ([north], [east]) from home. */
    fun square(inclusion: Boolean, half: Double, north: Double = 0.0, east: Double = 0.0) =
        FencePolygon(inclusion, listOf(-half to -half, half to -half, half to half, -half to half).map { (n, e) -> point(north + n, east + e) })

    fun SimAutopilot.loadFence(polygons: List<FencePolygon> = emptyList(), circles: List<FenceCircle> = emptyList()) =
        missionServer.load(MissionType.FENCE, PlanLists.fenceItems(PlanGeoFence(polygons, circles)))

    fun SimAutopilot.north(): Double = northEast(HOME, body.location).first

    fun SimAutopilot.reposition(north: Double, east: Double = 0.0, height: Float = 20f): CommandResult {
        val at = HOME.offset(north = north.m, east = east.m)
        return command(CommandRequest(192, param1 = -1f, x = (at.latitude * 1e7).roundToLong().toDouble(), y = (at.longitude * 1e7).roundToLong().toDouble(), z = height, frame = 6))
    }

    fun SimAutopilot.modeCommand(name: String, out: MutableList<SimOutput>): CommandResult =
        command(CommandRequest(176, param1 = 1f, param2 = FlightModes.customMode(autopilot, type, name)!!.toFloat()), out)

    fun List<SimOutput>.texts(): List<String> = filterIsInstance<SimOutput.Text>().map { it.text }

    /** An ArduCopter hovering 20 m above home in GUIDED. */
    fun hoveringCopter(): SimAutopilot {
        val ap = autopilot()
        ap.run(2.5)
        ap.mode("GUIDED") shouldBe CommandResult.ACCEPTED
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(22, z = 20f)) shouldBe CommandResult.ACCEPTED
        ap.runUntil(30.0) { it.activity is Activity.Hold }
        ap.drain()
        return ap
    }

    "an ArduCopter flying in GUIDED out of an inclusion polygon says so, returns (RTL, FENCE_ACTION 1) and never gets 10 m past the edge" {
        val ap = hoveringCopter()
        ap.params["FENCE_ENABLE"] shouldBe 0.0 // off by default: the station enables it
        ap.loadFence(listOf(square(inclusion = true, half = 100.0)))
        ap.reposition(north = 200.0) shouldBe CommandResult.ACCEPTED // no fence yet: a target outside is accepted
        ap.command(CommandRequest(Geofence.DO_FENCE_ENABLE, param1 = 1f)) shouldBe CommandResult.ACCEPTED
        ap.params["FENCE_ENABLE"] shouldBe 0.0 // the command does not persist
        val out = ArrayList<SimOutput>()
        var farthest = 0.0
        ap.runUntil(300.0, check = { out += it.drain(); farthest = maxOf(farthest, it.north()) }) { !it.armed }
        out.filterIsInstance<SimOutput.Text>().filter { it.text.contains("fence", ignoreCase = true) }.map { it.severity to it.text } shouldContainExactly listOf(
            Severity.NOTICE to "Polygon fence breached",
            Severity.NOTICE to "Fence breach cleared",
        )
        val status = out.filterIsInstance<SimOutput.FenceStatus>().single()
        status.breached shouldBe true
        status.type shouldBe 3 // FENCE_BREACH_BOUNDARY
        ap.modeName shouldBe "RTL"
        farthest shouldBeGreaterThan 100.0
        farthest shouldBeLessThan 110.0
        horizontalDistance(ap.body.location, HOME) shouldBeLessThan 2.0
    }

    "an ArduCopter refuses a GUIDED destination outside its enabled fence (FAILED) and stays where it is" {
        val ap = hoveringCopter()
        ap.loadFence(listOf(square(inclusion = true, half = 100.0)))
        ap.params.set("FENCE_ENABLE", 1.0)
        ap.run(1.0)
        ap.reposition(north = 150.0) shouldBe CommandResult.FAILED
        ap.reposition(north = 80.0) shouldBe CommandResult.ACCEPTED
        ap.run(40.0)
        ap.north() shouldBe (80.0 plusOrMinus 0.5)
        ap.modeName shouldBe "GUIDED"
    }

    "an ArduCopter mission whose leg crosses an exclusion circle breaches on entering it and returns, short of the next waypoint" {
        val ap = autopilot()
        ap.load(listOf(homeItem(), item(22, alt = 20.0), item(16, 200.0, 0.0, 20.0), item(16, 200.0, 100.0, 20.0), item(20, global = false)))
        ap.loadFence(circles = listOf(FenceCircle(inclusion = false, center = point(100.0, 0.0), radiusMetres = 20.0)))
        ap.params.set("FENCE_ENABLE", 1.0)
        ap.mode("GUIDED")
        ap.run(2.5)
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        val out = ArrayList<SimOutput>()
        var deepest = 0.0
        val center = HOME.offset(north = 100.m, east = 0.m)
        ap.runUntil(300.0, check = { out += it.drain(); deepest = maxOf(deepest, 20.0 - horizontalDistance(center, it.body.location)) }) { !it.armed }
        out.texts() shouldContain "Polygon fence breached" // uploaded circles belong to the polygon fence type
        ap.modeName shouldBe "RTL"
        ap.reached shouldNotContain 2
        deepest shouldBeGreaterThan 0.0
        deepest shouldBeLessThan 8.0
    }

    "with FENCE_ENABLE at its default 0 an ArduCopter flies out of the uploaded fence and nothing happens" {
        val ap = hoveringCopter()
        ap.loadFence(listOf(square(inclusion = true, half = 100.0)))
        ap.reposition(north = 200.0) shouldBe CommandResult.ACCEPTED
        val out = ArrayList<SimOutput>()
        ap.run(70.0) { out += it.drain() }
        ap.north() shouldBe (200.0 plusOrMinus 0.5)
        ap.modeName shouldBe "GUIDED"
        out.texts().filter { it.contains("fence", ignoreCase = true) }.shouldBeEmpty()
        out.filterIsInstance<SimOutput.FenceStatus>().shouldBeEmpty()
    }

    "a disarmed ArduCopter inside an exclusion zone takes no action, but will not arm while breaching it" {
        val ap = autopilot()
        ap.run(2.5)
        ap.params.set("FENCE_ENABLE", 1.0)
        ap.loadFence(circles = listOf(FenceCircle(inclusion = false, center = point(0.0, 0.0), radiusMetres = 50.0)))
        val out = ArrayList<SimOutput>()
        ap.run(10.0) { out += it.drain() }
        out.texts().shouldBeEmpty()
        ap.modeName shouldBe "STABILIZE"
        ap.armed shouldBe false
        out.filterIsInstance<SimOutput.FenceStatus>().single().breached shouldBe true // record_breach reports it armed or not
        ap.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.FAILED
        out.texts() shouldContain "Arm: Vehicle breaching Polygon fence"
        ap.command(CommandRequest(Geofence.DO_FENCE_ENABLE, param1 = 0f)) shouldBe CommandResult.ACCEPTED
        ap.armCommand() shouldBe CommandResult.ACCEPTED
    }

    "after a breach an ArduCopter does not act again while still outside; flown back in, the breach clears" {
        val ap = hoveringCopter()
        ap.loadFence(listOf(square(inclusion = true, half = 100.0)))
        ap.reposition(north = 200.0) shouldBe CommandResult.ACCEPTED
        ap.params.set("FENCE_ENABLE", 1.0)
        val out = ArrayList<SimOutput>()
        ap.runUntil(60.0, check = { out += it.drain() }) { it.modeName == "RTL" }
        ap.mode("GUIDED") shouldBe CommandResult.ACCEPTED // the station takes over just outside the edge
        ap.run(30.0) { out += it.drain() }
        ap.modeName shouldBe "GUIDED"
        ap.north() shouldBeGreaterThan 100.0
        ap.reposition(north = 50.0) shouldBe CommandResult.ACCEPTED
        ap.run(30.0) { out += it.drain() }
        out.texts().filter { it.contains("fence", ignoreCase = true) } shouldBe listOf("Polygon fence breached", "Fence breach cleared")
        ap.modeName shouldBe "GUIDED"
    }

    "an ArduPlane flying its mission out of an inclusion polygon returns (RTL) and refuses AUTO until it is back inside" {
        val ap = autopilot(type = VehicleType.FIXED_WING)
        ap.run(2.5)
        ap.load(listOf(homeItem(), item(22, alt = 40.0), item(16, 1500.0, 0.0, 60.0), item(16, 1500.0, 300.0, 60.0)))
        ap.loadFence(listOf(square(inclusion = true, half = 600.0)))
        ap.params.set("FENCE_ENABLE", 1.0)
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        val out = ArrayList<SimOutput>()
        var farthest = 0.0
        ap.runUntil(300.0, check = { out += it.drain(); farthest = maxOf(farthest, it.north()) }) { it.modeName == "RTL" }
        out.texts() shouldContain "Polygon fence breached"
        val refusal = ArrayList<SimOutput>()
        ap.modeCommand("AUTO", refusal) shouldBe CommandResult.FAILED // FENCE_OPTIONS bit 0, Plane's default
        refusal.filterIsInstance<SimOutput.Text>().map { it.severity to it.text } shouldContainExactly listOf(
            Severity.NOTICE to "Mode change to AUTO denied, in fence recovery",
        )
        ap.modeName shouldBe "RTL"
        ap.runUntil(120.0, check = { farthest = maxOf(farthest, it.north()) }) { it.north() < 500.0 }
        farthest shouldBeLessThan 700.0
        ap.modeCommand("AUTO", out) shouldBe CommandResult.ACCEPTED
    }

    "a PX4 multicopter whose mission crosses an exclusion circle holds (GF_ACTION 2, its default) just inside it" {
        val ap = autopilot(Autopilot.PX4)
        ap.params["GF_ACTION"] shouldBe 2.0
        ap.load(listOf(item(22, alt = 20.0), item(16, 200.0, 0.0, 20.0), item(16, 200.0, 100.0, 20.0)))
        ap.loadFence(circles = listOf(FenceCircle(inclusion = false, center = point(100.0, 0.0), radiusMetres = 20.0)))
        ap.run(2.5)
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        val out = ArrayList<SimOutput>()
        ap.runUntil(120.0, check = { out += it.drain() }) { it.modeName == "AUTO.LOITER" }
        out.filterIsInstance<SimOutput.Text>().map { it.severity to it.text } shouldContain (Severity.CRITICAL to "Failsafe activated")
        val stoppedAt = ap.body.location
        val center = HOME.offset(north = 100.m, east = 0.m)
        horizontalDistance(center, stoppedAt) shouldBe (19.5 plusOrMinus 0.5) // just in: checked every 200 ms at 5 m/s
        ap.run(30.0) { out += it.drain() }
        ap.modeName shouldBe "AUTO.LOITER"
        ap.armed shouldBe true
        horizontalDistance(ap.body.location, stoppedAt) shouldBeLessThan 6.0
        20.0 - horizontalDistance(center, ap.body.location) shouldBeLessThan 8.0
        out.texts().count { it.startsWith("Failsafe") } shouldBe 1
    }

    "PX4 with GF_ACTION 3 holds COM_FAIL_ACT_T seconds, then returns" {
        val ap = autopilot(Autopilot.PX4)
        ap.params.set("GF_ACTION", 3.0)
        ap.load(listOf(item(22, alt = 20.0), item(16, 200.0, 0.0, 20.0)))
        ap.loadFence(listOf(square(inclusion = true, half = 100.0)))
        ap.run(2.5)
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        val out = ArrayList<SimOutput>()
        ap.runUntil(120.0, check = { out += it.drain() }) { it.modeName == "AUTO.LOITER" }
        val heldAt = ap.time
        out.texts() shouldContain "Failsafe activated, entering Hold for 5 seconds"
        ap.north() shouldBe (101.0 plusOrMinus 1.0) // at the edge: checked every 200 ms at 5 m/s
        ap.runUntil(10.0) { it.modeName == "AUTO.RTL" }
        (ap.time - heldAt) shouldBe (5.0 plusOrMinus 0.25)
    }

    "PX4 drops an uploaded zone that does not contain home, and says why" {
        val ap = autopilot(Autopilot.PX4)
        ap.run(2.5)
        ap.loadFence(listOf(square(inclusion = true, half = 50.0, north = 500.0)))
        ap.run(0.5)
        ap.drain().filterIsInstance<SimOutput.Text>().map { it.severity to it.text } shouldContainExactly listOf(
            Severity.CRITICAL to "Geofence invalid, doesn't contain Home position",
        )
        ap.load(listOf(item(22, alt = 20.0), item(16, 100.0, 0.0, 20.0)))
        ap.command(CommandRequest(300)) shouldBe CommandResult.ACCEPTED
        val out = ArrayList<SimOutput>()
        ap.run(40.0) { out += it.drain() }
        ap.north() shouldBeGreaterThan 85.0 // at the last waypoint (NAV_ACC_RAD 10 m), outside the dropped zone
        out.texts().filter { it.startsWith("Failsafe") }.shouldBeEmpty()
    }

    "ArduPlane will not arm with FENCE_ENABLE set and no polygon uploaded (its FENCE_TYPE is polygons only)" {
        val ap = autopilot(type = VehicleType.FIXED_WING)
        ap.run(2.5)
        ap.params.set("FENCE_ENABLE", 1.0)
        val out = ArrayList<SimOutput>()
        ap.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.FAILED
        out.texts() shouldContain "Arm: Fences enabled, but none selected"
        ap.loadFence(listOf(square(inclusion = true, half = 500.0)))
        ap.armCommand() shouldBe CommandResult.ACCEPTED
    }
})
