package pod.e2e

import io.dronefleet.mavlink.common.AutopilotVersion
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldNotBeEmpty
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.mapNotNull
import kotlinx.coroutines.withTimeout
import io.kotest.matchers.doubles.shouldBeLessThan
import kotlin.math.abs
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleLost
import pod.core.vehicle.VehicleType
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.VehicleTiming
import pod.mavlink.action.UnknownMode
import pod.mavlink.command.CommandRejected
import pod.mavlink.action.VehicleDisarmed
import pod.mavlink.command.CommandResult
import pod.mavlink.command.CommandTimeout
import pod.mavlink.command.CommandTiming
import pod.mavlink.command.VehicleCommand
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.telemetry.ModeRole
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import pod.sim.fault.LossyRelay

class VehicleControlSpec : StringSpec({

    for ((autopilot, type) in listOf(Autopilot.ARDUPILOT to VehicleType.QUADROTOR, Autopilot.PX4 to VehicleType.QUADROTOR)) {
        "a ${autopilot.name} copter arms, takes off, goes to a point, lands and disarms, each step confirmed" {
            virtualRun { flying(SimVehicleConfig(systemId = 41, autopilot = autopilot, type = type)) { v, _ ->
                val home = v.telemetry.position.value!!.location
                Flights.keepArmedOnGround(v)
                v.action.arm()
                v.telemetry.armed.value shouldBe true
                v.action.takeoff(15.m)
                (v.telemetry.position.value!!.relativeAltitude.meters >= 14.0) shouldBe true
                val target = home.offset(north = 30.m, east = 20.m, up = 15.m)
                v.action.goto(target)
                v.action.awaitArrival(target, within = 2.m, timeout = 10.minutes)
                v.action.land()
                v.action.awaitLanded(timeout = 10.minutes)
                v.telemetry.position.value!!.location.distanceTo(target).meters.let { (it < 3.0) shouldBe true }
            } }
        }
    }

    for (autopilot in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
        "hold stops a ${autopilot.name} copter on its way to a point and keeps it there, at its height" {
            virtualRun { flying(SimVehicleConfig(systemId = 43, autopilot = autopilot)) { v, sim ->
                val home = v.telemetry.position.value!!.location
                Flights.keepArmedOnGround(v)
                v.action.arm()
                v.action.takeoff(15.m)
                val target = home.offset(north = 300.m, east = 0.m, up = 15.m)
                v.action.goto(target)
                withTimeout(10.minutes) { sim.state.first { it.groundSpeed.metersPerSecond > 3.0 } }
                v.action.hold()
                val stopped = sim.state.value.location
                // PX4's Hold is where its goto flies: choosing it again would let the copter fly on.
                // ArduCopter's LOITER would sink to the ground with nobody on the sticks.
                val still = withTimeout(5.minutes) { sim.state.first { it.groundSpeed.metersPerSecond < 0.1 && abs(it.climbRate.metersPerSecond) < 0.1 } }
                still.location.distanceTo(stopped).meters shouldBeLessThan 30.0
                abs(still.relativeAltitude.meters - 15.0) shouldBeLessThan 1.0
                still.armed shouldBe true
                v.telemetry.mode.value!!.name shouldBe FlightModes.forRole(autopilot, VehicleType.QUADROTOR, ModeRole.HOLD)
            } }
        }

        "over a link losing 30 % each way, a ${autopilot.name} copter still arms, takes off, goes to a point and lands" {
            virtualRun(seed = 11, up = LOSSY, down = LOSSY) {
                // Heartbeats cross the same lossy link: allow more silence before calling the vehicle lost.
                flying(SimVehicleConfig(systemId = 42, autopilot = autopilot), GroundStationConfig(lostAfter = 10.seconds)) { v, _ ->
                    val home = v.telemetry.position.value!!.location
                    Flights.keepArmedOnGround(v)
                    v.action.arm()
                    v.action.takeoff(10.m)
                    val target = home.offset(north = 25.m, east = 0.m, up = 10.m)
                    v.action.goto(target)
                    v.action.awaitArrival(target, within = 2.m, timeout = 10.minutes)
                    v.action.land()
                    v.action.awaitLanded(timeout = 10.minutes)
                    // The ground station sends little (heartbeats, a few commands), so fewer of its datagrams are there to drop.
                    counters(towardsGround = true).dropped shouldBeGreaterThan 10
                    counters(towardsGround = false).dropped shouldBeGreaterThan 0
                }
            }
        }
    }

    "refusals are typed: arming with a flat battery says why, takeoff while disarmed fails, an unknown command is unsupported" {
        virtualRun { flying(SimVehicleConfig(systemId = 43, initialCharge = 0.1)) { v, _ ->
            val arm = shouldThrow<CommandRejected> { v.action.arm() }
            arm.result shouldBe CommandResult.FAILED
            arm.statusTexts.shouldNotBeEmpty()
            arm.message!! shouldContain "Arm"
            v.telemetry.armed.value shouldBe false

            // Refused before anything is sent: a disarmed vehicle does not take off (PX4 would accept and sit on the ground).
            shouldThrow<VehicleDisarmed> { v.action.takeoff(10.m) }.message shouldBe "vehicle 43 is disarmed: arm it first to take off"
            shouldThrow<CommandRejected> { v.commands.send(VehicleCommand(31_000)) }.result shouldBe CommandResult.UNSUPPORTED
            shouldThrow<UnknownMode> { v.action.setMode("WARP") }.known.contains("GUIDED") shouldBe true
        } }
    }

    "a vehicle that stopped talking fails a command within its timeout, or as lost once its heartbeat is missed" {
        val quickCommands = VehicleTiming(commands = CommandTiming(timeout = 2.seconds))
        virtualRun { flying(SimVehicleConfig(systemId = 44), GroundStationConfig(lostAfter = 30.seconds, vehicleTiming = quickCommands)) { v, sim ->
            sim.stop()
            val error = shouldThrow<CommandTimeout> { withTimeout(5.seconds) { v.action.arm() } }
            error.waitingFor shouldBe "COMMAND_ACK"
        } }
        virtualRun { flying(SimVehicleConfig(systemId = 45), GroundStationConfig(lostAfter = 1.seconds)) { v, sim ->
            sim.stop()
            shouldThrow<VehicleLost> { withTimeout(5.seconds) { v.action.arm() } }.systemId shouldBe 45
        } }
    }

    "parameters read and write through to the simulated autopilot" {
        virtualRun { flying(SimVehicleConfig(systemId = 46)) { v, _ ->
            val speed = v.params.read("WPNAV_SPEED")
            speed.value shouldBe 500.0
            v.params.write("WPNAV_SPEED", 800.0).value shouldBe 800.0
            v.params.read("WPNAV_SPEED").value shouldBe 800.0
        } }
        virtualRun { flying(SimVehicleConfig(systemId = 47, autopilot = Autopilot.PX4)) { v, _ ->
            v.params.read("MAV_SYS_ID").let {
                it.value shouldBe 47.0
                it.type.isInteger shouldBe true
            }
            v.params.read("MPC_XY_CRUISE").value.shouldBeInstanceOf<Double>()
        } }
    }

    "asked with REQUEST_MESSAGE, a simulated autopilot describes itself: ArduPilot casts integer parameters, PX4 copies their bits" {
        for ((systemId, autopilot) in listOf(48 to Autopilot.ARDUPILOT, 49 to Autopilot.PX4)) {
            virtualRun { flying(SimVehicleConfig(systemId = systemId, autopilot = autopilot)) { v, _ ->
                coroutineScope {
                    val version = async(start = CoroutineStart.UNDISPATCHED) {
                        withTimeout(5.seconds) { v.messages.mapNotNull { it.message as? AutopilotVersion }.first() }
                    }
                    v.commands.send(VehicleCommand(512, param1 = 148f)).result shouldBe CommandResult.ACCEPTED
                    val capabilities = version.await().capabilities().value()
                    val (castBit, bytewiseBit) = 0x20000 to 0x10
                    (capabilities and castBit != 0) shouldBe (autopilot == Autopilot.ARDUPILOT)
                    (capabilities and bytewiseBit != 0) shouldBe (autopilot == Autopilot.PX4)
                    (capabilities and 0x4 != 0) shouldBe true // MISSION_INT
                }
            } }
        }
    }
})

private val LOSSY = LinkFaults(drop = 0.3, delay = 2.milliseconds)
