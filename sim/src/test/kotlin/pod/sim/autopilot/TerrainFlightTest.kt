package pod.sim.autopilot

import io.dronefleet.mavlink.common.DistanceSensor
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType
import pod.mavlink.MessageIds
import pod.mavlink.command.CommandResult
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.MissionServerFlavor
import pod.sim.SimMessages
import pod.sim.SimVehicleConfig
import pod.sim.world.Hill
import pod.sim.world.Rangefinder
import pod.sim.world.SimWorld
import pod.sim.world.Terrain
import kotlin.math.abs
import kotlin.math.roundToLong
import kotlin.time.TimeSource

/** A 12 m hill 80 m north of home, 15 m wide, on otherwise flat ground. */
private val HILL = Hill(80.m, 0.m, 12.m, 15.m)
private val TERRAIN = Terrain(HOME, listOf(HILL))

private fun overTerrain(autopilot: Autopilot = Autopilot.ARDUPILOT): SimAutopilot = SimAutopilot(
    autopilot, VehicleType.QUADROTOR, 1, HOME, 1.0,
    MissionServer(if (autopilot == Autopilot.PX4) MissionServerFlavor.PX4 else MissionServerFlavor.ARDUPILOT),
    readyAfter = 2.0, world = SimWorld(HOME.altitude.meters, TERRAIN),
)

/** Takes off in GUIDED to [alt] m above home. */
private fun SimAutopilot.up(alt: Float) {
    run(2.5)
    mode("GUIDED") shouldBe CommandResult.ACCEPTED
    armCommand() shouldBe CommandResult.ACCEPTED
    command(CommandRequest(22, z = alt)) shouldBe CommandResult.ACCEPTED
    runUntil(40.0) { it.state().landedState == LandedState.IN_AIR }
}

/** DO_REPOSITION as ArduPilot takes it: COMMAND_INT, relative altitude [alt]. */
private fun SimAutopilot.reposition(north: Double, east: Double, alt: Float) {
    val target = HOME.offset(north.m, east.m)
    val x = (target.latitude * 1e7).roundToLong().toDouble()
    val y = (target.longitude * 1e7).roundToLong().toDouble()
    command(CommandRequest(192, param1 = -1f, x = x, y = y, z = alt, frame = 6)) shouldBe CommandResult.ACCEPTED
}

class TerrainFlightTest : StringSpec({
    val messages = SimMessages(SimVehicleConfig(systemId = 1, rangefinder = Rangefinder()), TimeSource.Monotonic.markNow())
    fun distanceCm(ap: SimAutopilot): Int = (messages.build(MessageIds.DISTANCE_SENSOR, ap.state()) as DistanceSensor).currentDistance()

    "flying level over a hill, DISTANCE_SENSOR reports the height above the terrain below, dipping over the summit" {
        val ap = overTerrain()
        ap.up(25f)
        ap.reposition(160.0, 0.0, 25f)
        var lowest = Double.MAX_VALUE
        var compared = 0
        ap.runUntil(60.0, check = {
            val s = it.state()
            val truth = s.location.altitude.meters - TERRAIN.elevationAt(s.location).meters
            // Rounding to whole centimetres is the only error.
            abs(distanceCm(it) - truth * 100) shouldBeLessThan 0.51
            s.heightAboveGround.meters shouldBe (truth plusOrMinus 1e-9)
            // Level flight: the altitude above home stays put while the ground rises beneath.
            s.relativeAltitude.meters shouldBe (25.0 plusOrMinus 0.5)
            lowest = minOf(lowest, truth)
            compared++
        }) { it.state().target == null }
        compared shouldBeGreaterThan 100 // the pass lasted long enough to see the hill
        lowest shouldBe (25.0 - 12.0 plusOrMinus 0.5) // over the summit
        ap.state().heightAboveGround.meters shouldBe (25.0 plusOrMinus 0.5) // past the hill: flat again
    }

    "beyond the lidar's 40 m the reading is the out-of-range value, max + 1 m, and the sensor's limits ride along" {
        val ap = overTerrain()
        ap.up(55f)
        val message = messages.build(MessageIds.DISTANCE_SENSOR, ap.state()) as DistanceSensor
        message.currentDistance() shouldBe 4100
        message.minDistance() shouldBe 10
        message.maxDistance() shouldBe 4000
        message.orientation().value() shouldBe 25
        message.type().value() shouldBe 0
    }

    "a copter landing over a hill touches down on the hill, at the terrain's elevation there, and disarms" {
        for (flavor in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
            val ap = overTerrain(flavor)
            if (flavor == Autopilot.PX4) {
                ap.run(2.5)
                ap.armCommand() shouldBe CommandResult.ACCEPTED
                ap.command(CommandRequest(22, z = (HOME.altitude.meters + 30).toFloat())) shouldBe CommandResult.ACCEPTED
                ap.runUntil(40.0) { it.modeName == "AUTO.LOITER" }
                ap.command(CommandRequest(192, param1 = -1f, param2 = 1f, x = HOME.offset(80.m, 0.m).latitude, y = HOME.offset(80.m, 0.m).longitude, z = (HOME.altitude.meters + 30).toFloat())) shouldBe CommandResult.ACCEPTED
            } else {
                ap.up(30f)
                ap.reposition(80.0, 0.0, 30f)
            }
            ap.runUntil(60.0) { it.state().target == null }
            ap.command(CommandRequest(21)) shouldBe CommandResult.ACCEPTED
            ap.runUntil(120.0) { !it.armed }
            val s = ap.state()
            s.landedState shouldBe LandedState.ON_GROUND
            val summit = TERRAIN.elevationAt(s.location).meters
            summit - HOME.altitude.meters shouldBeGreaterThan 11.5
            s.location.altitude.meters shouldBe (summit plusOrMinus 0.05)
            s.heightAboveGround.meters shouldBe (0.0 plusOrMinus 0.05)
        }
    }

    "without a terrain the ground stays flat at home's altitude, as before" {
        val ap = autopilot()
        ap.up(20f)
        ap.reposition(80.0, 0.0, 20f)
        ap.runUntil(60.0, check = { it.ground shouldBe HOME.altitude.meters }) { it.state().target == null }
        ap.state().heightAboveGround.meters shouldBe (20.0 plusOrMinus 0.5)
    }
})
