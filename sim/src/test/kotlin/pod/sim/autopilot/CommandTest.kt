package pod.sim.autopilot

import pod.mavlink.command.CommandResult
import pod.core.vehicle.Severity
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.MissionServerFlavor
import pod.sim.flight.horizontalDistance
import kotlin.math.roundToLong

class CommandTest : StringSpec({

    fun texts(out: List<SimOutput>) = out.filterIsInstance<SimOutput.Text>()

    "ArduPilot refuses to arm on a low battery with FAILED and a CRITICAL PreArm STATUSTEXT" {
        val ap = autopilot(charge = 0.1)
        ap.run(2.5)
        val out = ArrayList<SimOutput>()
        ap.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.FAILED
        texts(out) shouldContain SimOutput.Text(Severity.CRITICAL, "PreArm: Battery 1 below minimum arming voltage")
        ap.armed shouldBe false
        ap.command(CommandRequest(400, param1 = 1f, param2 = 21196f)) shouldBe CommandResult.ACCEPTED // forced
        ap.armed shouldBe true
    }

    "PX4 refuses to arm on a low battery with TEMPORARILY_REJECTED and says why" {
        val ap = autopilot(Autopilot.PX4, charge = 0.1)
        ap.run(2.5)
        val out = ArrayList<SimOutput>()
        ap.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.TEMPORARILY_REJECTED
        texts(out).map { it.text } shouldContain "Arming denied: low battery"
    }

    "arming before the GPS is ready is refused; once ready it is accepted, and arming twice is accepted again" {
        val ap = autopilot()
        val out = ArrayList<SimOutput>()
        ap.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.FAILED
        texts(out).map { it.text } shouldContain "Arm: AHRS: waiting for home"
        ap.run(2.5)
        ap.armCommand() shouldBe CommandResult.ACCEPTED
        ap.armCommand() shouldBe CommandResult.ACCEPTED
    }

    "ArduPilot answers a refused command with the COMMAND_ACK first and the STATUSTEXT lines after it; PX4 the other way round" {
        val ardu = autopilot(charge = 0.1)
        val out = ArrayList<SimOutput>()
        ardu.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.FAILED
        out.map { it::class.simpleName } shouldBe listOf("Ack", "Text", "Text", "Text") // still booting, and a flat battery
        texts(out).map { it.text } shouldBe listOf("Arm: Accels inconsistent", "Arm: AHRS: waiting for home", "PreArm: Battery 1 below minimum arming voltage")
        val px4 = autopilot(Autopilot.PX4, charge = 0.1)
        out.clear()
        px4.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.TEMPORARILY_REJECTED
        out.map { it::class.simpleName } shouldBe listOf("Text", "Ack")
    }

    "a booting ArduPilot: no home until its estimator has an origin, then one HOME_POSITION; sensors settle later and it arms" {
        val ap = SimAutopilot(
            Autopilot.ARDUPILOT, VehicleType.FIXED_WING, 1, HOME, 1.0,
            MissionServer(MissionServerFlavor.ARDUPILOT), readyAfter = 20.0, sensorsReadyAfter = 23.0,
        )
        val early = ArrayList<SimOutput>()
        ap.run(1.0)
        ap.command(CommandRequest(400, param1 = 1f), early) shouldBe CommandResult.FAILED
        texts(early).map { it.text } shouldBe listOf("Arm: Accels inconsistent", "Arm: AHRS: waiting for home")
        ap.state().positionReady shouldBe false
        val announced = ArrayList<SimOutput>()
        ap.run(19.5) { announced += it.drain() }
        announced.count { it == SimOutput.HomeChanged } shouldBe 1
        ap.positionReady shouldBe true
        val homeSet = ArrayList<SimOutput>()
        ap.command(CommandRequest(400, param1 = 1f), homeSet) shouldBe CommandResult.FAILED // home set, sensors still settling
        texts(homeSet).map { it.text } shouldBe listOf("Arm: Accels inconsistent")
        ap.run(3.0)
        ap.armCommand() shouldBe CommandResult.ACCEPTED
    }

    "ArduPilot stores what it is sent: out-of-range values and STAT_BOOTCNT, integers clamped to their type" {
        val ardu = autopilot()
        ardu.paramResponder.set("WPNAV_SPEED", 1e9f)
        ardu.drain().filterIsInstance<SimOutput.Param>().size shouldBe 1
        ardu.params["WPNAV_SPEED"] shouldBe 1e9
        ardu.paramResponder.set("STAT_BOOTCNT", 9f)
        texts(ardu.drain()) shouldBe emptyList()
        ardu.params["STAT_BOOTCNT"] shouldBe 9.0
        ardu.paramResponder.set("RTL_ALT", 1e12f)
        ardu.drain()
        ardu.params["RTL_ALT"] shouldBe 2147483647.0
        ardu.paramResponder.set("LAND_SPEED", 1e6f)
        ardu.drain()
        ardu.params["LAND_SPEED"] shouldBe 32767.0
    }

    "ArduCopter refuses to arm in AUTO and to enter AUTO armed on the ground without a take-off item" {
        val ap = autopilot()
        ap.run(2.5)
        ap.mode("AUTO") shouldBe CommandResult.FAILED // no mission
        ap.load(listOf(homeItem(), item(16, 10.0, 0.0, 10.0)))
        ap.mode("AUTO") shouldBe CommandResult.ACCEPTED
        val out = ArrayList<SimOutput>()
        ap.command(CommandRequest(400, param1 = 1f), out) shouldBe CommandResult.FAILED
        texts(out).map { it.text } shouldContain "Arm: Mode not armable"
        ap.mode("GUIDED")
        ap.armCommand()
        out.clear()
        ap.command(CommandRequest(300), out) shouldBe CommandResult.FAILED
        texts(out).map { it.text } shouldContain "Auto: Missing Takeoff Cmd"
        ap.command(CommandRequest(300, param1 = 2f)) shouldBe CommandResult.DENIED // first/last item not supported
    }

    "PX4 rejects an unknown mode and AUTO.MISSION without a mission with TEMPORARILY_REJECTED" {
        val ap = autopilot(Autopilot.PX4)
        ap.command(CommandRequest(176, param1 = 1f, param2 = 4f, param3 = 4f)) shouldBe CommandResult.TEMPORARILY_REJECTED
        ap.command(CommandRequest(176, param1 = 1f, param2 = 42f)) shouldBe CommandResult.TEMPORARILY_REJECTED
        ap.command(CommandRequest(176, param1 = 1f, param2 = 3f)) shouldBe CommandResult.ACCEPTED
        ap.modeName shouldBe "POSCTL"
    }

    "ArduPilot answers the legacy SET_MODE message with a COMMAND_ACK for command 11" {
        val ap = autopilot()
        ap.run(2.5) // GUIDED needs a position
        ap.commands.handleSetMode(1, 4, 255, 190)
        ap.drain().filterIsInstance<SimOutput.Ack>().single() shouldBe SimOutput.Ack(11, CommandResult.ACCEPTED, 0, 255, 190)
        ap.modeName shouldBe "GUIDED"
        ap.commands.handleSetMode(1, 99, 255, 190)
        ap.drain().filterIsInstance<SimOutput.Ack>().single().result shouldBe CommandResult.FAILED
    }

    "takeoff while disarmed: ArduCopter FAILED; PX4 accepts, switches to AUTO.TAKEOFF and climbs once armed" {
        val copter = autopilot()
        copter.run(2.5)
        copter.mode("GUIDED")
        copter.command(CommandRequest(22, z = 10f)) shouldBe CommandResult.FAILED
        val px4 = autopilot(Autopilot.PX4)
        px4.run(2.5)
        px4.command(CommandRequest(22, z = Float.NaN)) shouldBe CommandResult.ACCEPTED
        px4.modeName shouldBe "AUTO.TAKEOFF"
        px4.run(5.0)
        px4.body.onGround shouldBe true
        px4.armCommand() shouldBe CommandResult.ACCEPTED
        px4.runUntil(30.0) { it.modeName == "AUTO.LOITER" }
        px4.body.location.altitude.meters - HOME.altitude.meters shouldBe (2.5 plusOrMinus 0.3) // MIS_TAKEOFF_ALT
    }

    "PX4: a NAV_TAKEOFF resent while climbing (its ack was lost) keeps climbing to the altitude asked, not to MIS_TAKEOFF_ALT" {
        val px4 = autopilot(Autopilot.PX4)
        px4.run(2.5)
        px4.armCommand() shouldBe CommandResult.ACCEPTED
        val target = (HOME.altitude.meters + 10.0).toFloat()
        px4.command(CommandRequest(22, z = target)) shouldBe CommandResult.ACCEPTED
        px4.runUntil(30.0) { it.body.location.altitude.meters - HOME.altitude.meters >= 2.0 }
        // The resend finds the vehicle above MIS_TAKEOFF_ALT's 2.5 m - 1: it must not stop there.
        px4.command(CommandRequest(22, z = target)) shouldBe CommandResult.ACCEPTED
        px4.runUntil(30.0) { it.modeName == "AUTO.LOITER" }
        px4.body.location.altitude.meters - HOME.altitude.meters shouldBe (10.0 plusOrMinus 0.5)
    }

    "ArduCopter takes off in GUIDED, refuses a disarm in the air, lands in LAND and disarms on the ground" {
        val ap = autopilot()
        ap.run(2.5)
        ap.mode("GUIDED")
        ap.armCommand()
        ap.command(CommandRequest(22, z = 15f, frame = 6)) shouldBe CommandResult.DENIED // COMMAND_INT wants the relative-alt frame
        ap.command(CommandRequest(22, z = 15f)) shouldBe CommandResult.ACCEPTED
        ap.runUntil(30.0) { it.state().landedState == LandedState.IN_AIR }
        ap.body.location.altitude.meters - HOME.altitude.meters shouldBe (15.0 plusOrMinus 0.3)
        ap.command(CommandRequest(400, param1 = 0f)) shouldBe CommandResult.FAILED
        ap.command(CommandRequest(21)) shouldBe CommandResult.ACCEPTED
        ap.modeName shouldBe "LAND"
        ap.state().landedState shouldBe LandedState.LANDING
        ap.runUntil(60.0) { !it.armed }
        ap.state().landedState shouldBe LandedState.ON_GROUND
    }

    "DO_REPOSITION: ArduPilot wants COMMAND_INT; as COMMAND_INT in GUIDED the copter flies there and hovers" {
        val ap = autopilot()
        ap.run(2.5)
        ap.mode("GUIDED")
        ap.armCommand()
        ap.command(CommandRequest(22, z = 10f))
        ap.run(8.0)
        val target = HOME.offset(north = 60.m, east = (-40).m)
        val lat = (target.latitude * 1e7).roundToLong().toDouble()
        val lon = (target.longitude * 1e7).roundToLong().toDouble()
        ap.command(CommandRequest(192, param1 = -1f, x = target.latitude, y = target.longitude, z = 30f)) shouldBe CommandResult.UNSUPPORTED
        ap.command(CommandRequest(192, param1 = -1f, x = lat, y = lon, z = 30f, frame = 6)) shouldBe CommandResult.ACCEPTED
        ap.run(40.0)
        horizontalDistance(ap.body.location, target) shouldBeLessThan 0.5
        ap.body.location.altitude.meters - HOME.altitude.meters shouldBe (30.0 plusOrMinus 0.3)
    }

    "PX4 accepts DO_REPOSITION as COMMAND_LONG and holds there; a plane circles the new point" {
        val ap = autopilot(Autopilot.PX4, VehicleType.FIXED_WING)
        ap.run(2.5)
        ap.command(CommandRequest(22, z = Float.NaN))
        ap.armCommand()
        ap.runUntil(60.0) { it.modeName == "AUTO.LOITER" }
        val target = HOME.offset(north = 500.m, east = 0.m)
        ap.command(CommandRequest(192, param1 = -1f, param2 = 1f, x = target.latitude, y = target.longitude, z = (HOME.altitude.meters + 80).toFloat())) shouldBe CommandResult.ACCEPTED
        ap.run(200.0)
        horizontalDistance(ap.body.location, target) shouldBe (80.0 plusOrMinus 12.0) // NAV_LOITER_RAD
    }

    "commands a flavour does not have are UNSUPPORTED" {
        autopilot().command(CommandRequest(42424)) shouldBe CommandResult.UNSUPPORTED
        autopilot(Autopilot.PX4).command(CommandRequest(193, param1 = 0f)) shouldBe CommandResult.UNSUPPORTED
        autopilot(type = VehicleType.FIXED_WING).command(CommandRequest(193, param1 = 0f)) shouldBe CommandResult.UNSUPPORTED
        autopilot(type = VehicleType.FIXED_WING).command(CommandRequest(21)) shouldBe CommandResult.UNSUPPORTED
        autopilot().command(CommandRequest(189)) shouldBe CommandResult.FAILED // no DO_LAND_START in the mission
    }

    "PREFLIGHT_CALIBRATION answers IN_PROGRESS with rising progress, then ACCEPTED; armed it is refused" {
        val ap = autopilot()
        ap.command(CommandRequest(241, param3 = 1f)) shouldBe CommandResult.IN_PROGRESS
        val acks = ArrayList<SimOutput.Ack>()
        ap.runUntil(5.0, check = { acks += it.drain().filterIsInstance<SimOutput.Ack>() }) { acks.any { it.result == CommandResult.ACCEPTED } }
        acks.map { it.result to it.progress } shouldBe listOf(CommandResult.IN_PROGRESS to 25, CommandResult.IN_PROGRESS to 50, CommandResult.IN_PROGRESS to 75, CommandResult.ACCEPTED to 0)
        ap.time shouldBe (2.0 plusOrMinus 0.06)
        ap.run(1.0)
        ap.armCommand()
        ap.command(CommandRequest(241, param3 = 1f)) shouldBe CommandResult.TEMPORARILY_REJECTED
    }

    "DO_CHANGE_SPEED changes the cruise speed; ArduPilot denies a non-positive speed" {
        val ap = autopilot()
        ap.command(CommandRequest(178, param1 = 1f, param2 = 8f)) shouldBe CommandResult.ACCEPTED
        ap.performance().cruise shouldBe 8.0
        ap.command(CommandRequest(178, param1 = 1f, param2 = -1f)) shouldBe CommandResult.DENIED
        autopilot(Autopilot.PX4).command(CommandRequest(178, param1 = 1f, param2 = -1f)) shouldBe CommandResult.ACCEPTED
    }

    "DO_SET_HOME moves home to the current location or to the given one" {
        val ap = autopilot()
        val there = HOME.offset(north = 100.m, east = 0.m)
        ap.command(CommandRequest(179, x = there.latitude, y = there.longitude, z = 150f)) shouldBe CommandResult.ACCEPTED
        horizontalDistance(ap.home, there) shouldBeLessThan 0.1
        ap.home.altitude.meters shouldBe (150.0 plusOrMinus 1e-3)
        ap.command(CommandRequest(179, param1 = 1f)) shouldBe CommandResult.ACCEPTED
        ap.home shouldBe ap.body.location
    }

    "parameters: ArduPilot sends floats, PX4 sends INT32 bytewise; writes echo the stored value and change the flight" {
        val ardu = autopilot()
        ardu.paramResponder.set("WPNAV_SPEED", 1000f)
        val echo = ardu.drain().filterIsInstance<SimOutput.Param>().single()
        ardu.params.at(echo.index)!!.name shouldBe "WPNAV_SPEED"
        ardu.params.wireValue(echo.index) shouldBe 1000f
        ardu.performance().cruise shouldBe 10.0
        ardu.paramResponder.set("DISARM_DELAY", 5f)
        ardu.params.wireValue(ardu.params.index("DISARM_DELAY")!!) shouldBe 5f
        ardu.paramResponder.set("NO_SUCH_PARAM", 1f)
        ardu.drain().filterIsInstance<SimOutput.Param>().size shouldBe 1 // DISARM_DELAY only; the unknown one is ignored
        ardu.paramResponder.set("SYSID_SW_TYPE", 3f)
        val out = ardu.drain()
        texts(out).map { it.text } shouldContain "Param write denied (SYSID_SW_TYPE)"
        ardu.params["SYSID_SW_TYPE"] shouldBe 10.0

        val px4 = autopilot(Autopilot.PX4)
        val sysId = px4.params.index("MAV_SYS_ID")!!
        px4.params.wireValue(sysId).toRawBits() shouldBe 1
        px4.paramResponder.set("MAV_SYS_ID", Float.fromBits(7))
        px4.drain().filterIsInstance<SimOutput.Param>().single().index shouldBe sysId
        px4.params["MAV_SYS_ID"] shouldBe 7.0
        px4.params.wireValue(sysId).toRawBits() shouldBe 7
        px4.paramResponder.set("MPC_XY_CRUISE", 8f)
        px4.drain()
        px4.params.wireValue(px4.params.index("MPC_XY_CRUISE")!!) shouldBe 8f

        px4.paramResponder.list()
        val listed = px4.drain().filterIsInstance<SimOutput.Param>()
        listed.map { it.index } shouldBe (0 until px4.params.count).toList()
        px4.paramResponder.read("", 1)
        px4.paramResponder.read("NAV_ACC_RAD", -1)
        px4.paramResponder.read("NOPE", -1)
        px4.drain().filterIsInstance<SimOutput.Param>().map { it.index } shouldBe listOf(1, px4.params.index("NAV_ACC_RAD"))
    }

    "a vehicle armed on the ground that never takes off disarms itself after the flavour's delay" {
        val ap = autopilot(Autopilot.PX4)
        ap.run(2.5)
        ap.armCommand()
        ap.run(9.0)
        ap.armed shouldBe true
        ap.run(1.5)
        ap.armed shouldBe false
        autopilot(type = VehicleType.FIXED_WING).apply { run(2.5); arm(); run(60.0) }.armed shouldBe true
        emptyList<Int>().shouldBeEmpty()
    }
})
