package pod.sim.autopilot

import pod.mavlink.telemetry.Px4CustomMode
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.command.CommandResult
import pod.mavlink.command.MavCommands.DO_ORBIT
import pod.mavlink.telemetry.FlightModes
import pod.sim.flight.horizontalDistance
import kotlin.math.roundToLong

/**
 * PX4's DO_ORBIT: a multicopter enters the orbit mode (POSCTL.ORBIT) and circles at the radius,
 * a fixed wing circles in Hold; the sign of the radius is the direction. Directions are read from
 * the flown track's signed area (see [Track.signedArea]: clockwise positive).
 */
class OrbitTest : StringSpec({

    /** A PX4 vehicle of [type] that took off and holds in AUTO.LOITER. */
    fun px4InTheAir(type: VehicleType): SimAutopilot = autopilot(Autopilot.PX4, type).also { ap ->
        ap.run(2.5)
        ap.command(CommandRequest(22, z = if (type.isMultirotor) (HOME.altitude.meters + 10).toFloat() else Float.NaN)) shouldBe CommandResult.ACCEPTED
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.runUntil(90.0) { it.modeName == "AUTO.LOITER" }
    }

    /** DO_ORBIT as COMMAND_LONG around [center] at [relAlt] m above home. */
    fun orbitLong(radius: Float, center: Location?, relAlt: Double?, speed: Float = Float.NaN) = CommandRequest(
        DO_ORBIT, param1 = radius, param2 = speed, param3 = Float.NaN, param4 = Float.NaN,
        x = center?.latitude ?: Double.NaN, y = center?.longitude ?: Double.NaN,
        z = relAlt?.let { (HOME.altitude.meters + it).toFloat() } ?: Float.NaN,
    )

    /** DO_ORBIT as COMMAND_INT in GLOBAL_INT (x/y degE7, z AMSL). */
    fun orbitInt(radius: Float, center: Location, relAlt: Double, speed: Float = Float.NaN) = CommandRequest(
        DO_ORBIT, param1 = radius, param2 = speed, param3 = Float.NaN, param4 = Float.NaN,
        x = (center.latitude * 1e7).roundToLong().toDouble(), y = (center.longitude * 1e7).roundToLong().toDouble(),
        z = (HOME.altitude.meters + relAlt).toFloat(), frame = 5,
    )

    fun SimAutopilot.heartbeatMode(): String = FlightModes.decode(autopilot, type, state().customMode).name

    val center = HOME.offset(north = 40.m, east = 20.m)

    "PX4 multicopter: DO_ORBIT with +30 m circles clockwise at 30 m and the commanded speed; the heartbeat shows POSCTL.ORBIT" {
        val ap = px4InTheAir(VehicleType.QUADROTOR)
        ap.command(orbitLong(30f, center, 15.0, speed = 4f)) shouldBe CommandResult.ACCEPTED
        ap.heartbeatMode() shouldBe "POSCTL.ORBIT"
        ap.state().customMode shouldBe Px4CustomMode.pack(main = 3, sub = 1)
        ap.run(30.0) // onto the circle
        val track = ap.track(center, 60.0)
        track.meanRadius shouldBe (30.0 plusOrMinus 4.5)
        track.signedArea shouldBeGreaterThan 0.0
        track.meanSpeed shouldBe (4.0 plusOrMinus 0.4)
        ap.body.location.altitude.meters - HOME.altitude.meters shouldBe (15.0 plusOrMinus 0.5)
    }

    "PX4 multicopter: DO_ORBIT as COMMAND_INT with -30 m circles counter-clockwise" {
        val ap = px4InTheAir(VehicleType.QUADROTOR)
        ap.command(orbitInt(-30f, center, 15.0, speed = 4f)) shouldBe CommandResult.ACCEPTED
        ap.run(30.0)
        val track = ap.track(center, 60.0)
        track.meanRadius shouldBe (30.0 plusOrMinus 4.5)
        track.signedArea shouldBeLessThan 0.0
    }

    "PX4 multicopter: the orbit speed defaults to 1 m/s and is limited to a 2 m/s² centripetal acceleration" {
        val slow = px4InTheAir(VehicleType.QUADROTOR)
        slow.command(orbitLong(20f, center, 10.0)) shouldBe CommandResult.ACCEPTED
        slow.run(40.0)
        slow.track(center, 40.0).meanSpeed shouldBe (1.0 plusOrMinus 0.15)

        val fast = px4InTheAir(VehicleType.QUADROTOR)
        fast.command(orbitLong(8f, center, 10.0, speed = 10f)) shouldBe CommandResult.ACCEPTED
        fast.run(30.0)
        val track = fast.track(center, 30.0)
        track.meanSpeed shouldBe (4.0 plusOrMinus 0.4) // √(2 m/s² · 8 m)
        track.meanRadius shouldBe (8.0 plusOrMinus 1.2)
    }

    "PX4 multicopter: a radius outside 1 m..MC_ORBIT_RAD_MAX is accepted, then reported and the vehicle holds where it is" {
        for (radius in listOf(0f, 2000f)) {
            val ap = px4InTheAir(VehicleType.QUADROTOR)
            val out = ArrayList<SimOutput>()
            ap.command(orbitLong(radius, center, 15.0, speed = 4f), out) shouldBe CommandResult.ACCEPTED
            out.map { it::class.simpleName } shouldBe listOf("Ack", "Text")
            out.filterIsInstance<SimOutput.Text>().map { it.text } shouldContain "Orbit radius limit exceeded"
            ap.modeName shouldBe "POSCTL.ORBIT"
            val here = ap.body.location
            ap.run(20.0)
            horizontalDistance(ap.body.location, here) shouldBeLessThan 1.0
        }
    }

    "PX4 multicopter: a DO_REPOSITION with the change-mode flag leaves the orbit for AUTO.LOITER and flies to the point" {
        val ap = px4InTheAir(VehicleType.QUADROTOR)
        ap.command(orbitLong(30f, center, 15.0, speed = 4f)) shouldBe CommandResult.ACCEPTED
        ap.run(40.0)
        val target = HOME.offset(north = (-50).m, east = 30.m)
        ap.command(CommandRequest(192, param1 = -1f, param2 = 1f, x = target.latitude, y = target.longitude, z = (HOME.altitude.meters + 12).toFloat())) shouldBe
            CommandResult.ACCEPTED
        ap.heartbeatMode() shouldBe "AUTO.LOITER"
        ap.run(60.0)
        horizontalDistance(ap.body.location, target) shouldBeLessThan 0.5
        ap.track(target, 10.0).meanSpeed shouldBeLessThan 0.05
    }

    "PX4 multicopter: a DO_ORBIT on the ground changes the mode and flies nothing; the orbit mode refuses arming; armed without a position it is rejected" {
        val ap = autopilot(Autopilot.PX4)
        ap.run(2.5)
        ap.command(orbitLong(30f, center, 15.0)) shouldBe CommandResult.ACCEPTED // Commander allows any mode change disarmed
        ap.heartbeatMode() shouldBe "POSCTL.ORBIT"
        ap.run(5.0)
        ap.body.onGround shouldBe true
        val out = ArrayList<SimOutput>()
        ap.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.TEMPORARILY_REJECTED
        out.filterIsInstance<SimOutput.Text>().map { it.text } shouldContain "Arming denied: mode not armable"

        val booting = autopilot(Autopilot.PX4)
        booting.command(CommandRequest(400, param1 = 1f, param2 = 21196f)) shouldBe CommandResult.ACCEPTED // forced: no position yet
        val rejected = ArrayList<SimOutput>()
        booting.command(orbitLong(30f, center, 15.0), rejected) shouldBe CommandResult.TEMPORARILY_REJECTED
        rejected.map { it::class.simpleName } shouldBe listOf("Text", "Ack")
        rejected.filterIsInstance<SimOutput.Text>().map { it.text } shouldContain "Orbit command rejected"
    }

    "PX4 multicopter: DO_SET_MODE to POSCTL.ORBIT selects plain POSCTL" {
        val ap = px4InTheAir(VehicleType.QUADROTOR)
        ap.mode("POSCTL.ORBIT") shouldBe CommandResult.ACCEPTED
        ap.modeName shouldBe "POSCTL"
    }

    "ArduPilot has no DO_ORBIT" {
        autopilot().command(orbitLong(30f, center, 15.0)) shouldBe CommandResult.UNSUPPORTED
        autopilot(type = VehicleType.FIXED_WING).command(orbitLong(30f, center, 15.0)) shouldBe CommandResult.UNSUPPORTED
    }

    val far = HOME.offset(north = 500.m, east = 200.m)

    "PX4 fixed wing: DO_ORBIT holds in AUTO.LOITER circling the point, +150 m clockwise, -150 m counter-clockwise" {
        for ((radius, clockwise) in listOf(150f to true, -150f to false)) {
            val ap = px4InTheAir(VehicleType.FIXED_WING)
            ap.command(orbitInt(radius, far, 80.0)) shouldBe CommandResult.ACCEPTED
            ap.heartbeatMode() shouldBe "AUTO.LOITER"
            ap.run(120.0)
            val track = ap.track(far, 130.0) // two laps at 15 m/s
            track.meanRadius shouldBe (150.0 plusOrMinus 22.5)
            if (clockwise) track.signedArea shouldBeGreaterThan 0.0 else track.signedArea shouldBeLessThan 0.0
            ap.body.location.altitude.meters - HOME.altitude.meters shouldBe (80.0 plusOrMinus 3.0)
        }
    }

    "PX4 fixed wing: DO_ORBIT without a radius circles at NAV_LOITER_RAD; a DO_REPOSITION afterwards circles the new point" {
        val ap = px4InTheAir(VehicleType.FIXED_WING)
        ap.command(orbitLong(Float.NaN, far, 80.0)) shouldBe CommandResult.ACCEPTED
        ap.run(120.0)
        ap.track(far, 70.0).meanRadius shouldBe (80.0 plusOrMinus 12.0)
        val target = HOME.offset(north = (-300).m, east = 0.m)
        ap.command(CommandRequest(192, param1 = -1f, param2 = 1f, x = target.latitude, y = target.longitude, z = (HOME.altitude.meters + 80).toFloat())) shouldBe
            CommandResult.ACCEPTED
        ap.modeName shouldBe "AUTO.LOITER"
        ap.run(150.0)
        ap.track(target, 70.0).meanRadius shouldBe (80.0 plusOrMinus 12.0)
    }
})
