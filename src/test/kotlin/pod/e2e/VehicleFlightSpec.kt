package pod.e2e

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlin.math.abs
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.mapNotNull
import kotlinx.coroutines.flow.take
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.withTimeout
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType
import pod.e2e.Flights.recordReached
import pod.mavlink.GroundStation
import pod.mavlink.command.MavCommands
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig

class VehicleFlightSpec : StringSpec({

    "an ArduPilot copter flies takeoff, five waypoints, two loiter turns and RTL in order, and ends landed and disarmed at home" {
        virtualRun { flying(SimVehicleConfig(systemId = 31)) { vehicle, _ ->
            val home = SimVehicleConfig.DEFAULT_HOME
            val mission = Flights.copterSurvey(home)
            vehicle.mission.upload(mission)
            val (reached, recording) = recordReached(vehicle)
            Flights.keepArmedOnGround(vehicle)
            vehicle.action.arm()
            vehicle.action.startMission()
            vehicle.action.awaitLanded(timeout = 20.minutes)
            recording.cancel()
            reached shouldBe (1..8).toList()
            val end = vehicle.telemetry.position.value!!
            end.location.distanceTo(home).meters shouldBeLessThan 3.0
            vehicle.telemetry.landedState.value shouldBe LandedState.ON_GROUND
            vehicle.telemetry.armed.value shouldBe false
        } }
    }

    "an ArduPilot plane flies its circuit and lands through the landing sequence, disarmed on the runway" {
        virtualRun { flying(SimVehicleConfig(systemId = 32, type = VehicleType.FIXED_WING)) { vehicle, _ ->
            val home = SimVehicleConfig.DEFAULT_HOME
            vehicle.mission.upload(Flights.planeCircuit(home))
            // ArduPlane arms a mission holding DO_LAND_START only with RTL_AUTOLAND set (AP_Arming_Plane::mission_checks).
            vehicle.params.write("RTL_AUTOLAND", 2.0)
            val (reached, recording) = recordReached(vehicle)
            Flights.keepArmedOnGround(vehicle)
            vehicle.action.arm()
            vehicle.action.startMission()
            // It gets airborne on its own takeoff item.
            withTimeout(10.minutes) { vehicle.telemetry.landedState.first { it == LandedState.IN_AIR } }
            vehicle.action.awaitLanded(timeout = 30.minutes)
            recording.cancel()
            reached shouldBe listOf(1, 2, 3, 4, 6, 7)
            vehicle.telemetry.position.value!!.location.distanceTo(home).meters shouldBeLessThan 60.0
        } }
    }

    "camera items in a mission are photographed where the vehicle is when it reaches them" {
        virtualRun { flying(SimVehicleConfig(systemId = 34, autopilot = Autopilot.PX4)) { vehicle, sim ->
            val home = SimVehicleConfig.DEFAULT_HOME
            val a = home.offset(30.m, 0.m)
            val b = home.offset(30.m, 30.m)
            val shoot = { seq: Int -> Flights.item(seq, MavCommands.DO_DIGICAM_CONTROL).copy(frame = 2, x = 1) }
            vehicle.mission.upload(
                listOf(
                    Flights.item(0, MavCommands.NAV_TAKEOFF, altitude = 15.0),
                    Flights.item(1, MavCommands.NAV_WAYPOINT, a, 15.0), shoot(2),
                    Flights.item(3, MavCommands.NAV_WAYPOINT, b, 15.0), shoot(4),
                    Flights.item(5, MavCommands.NAV_RETURN_TO_LAUNCH),
                ),
            )
            Flights.keepArmedOnGround(vehicle)
            vehicle.action.arm()
            vehicle.action.startMission()
            vehicle.action.awaitLanded(timeout = 20.minutes)
            val photos = sim.photos.value
            photos.map { it.missionSeq } shouldBe listOf(2, 4)
            photos[0].location.distanceTo(a).meters shouldBeLessThan 11.0 // PX4's NAV_ACC_RAD is 10 m
            photos[1].location.distanceTo(b).meters shouldBeLessThan 11.0
        } }
    }

    for (autopilot in listOf(Autopilot.ARDUPILOT, Autopilot.PX4)) {
        "a ${autopilot.name} copter paused mid-mission holds position and altitude, and continues at the same item" {
            virtualRun { flying(SimVehicleConfig(systemId = 33, autopilot = autopilot)) { vehicle, _ ->
                val home = SimVehicleConfig.DEFAULT_HOME
                vehicle.mission.upload(Flights.copterSurvey(home))
                Flights.keepArmedOnGround(vehicle)
                vehicle.action.arm()
                vehicle.action.startMission()
                withTimeout(20.minutes) { vehicle.telemetry.missionCurrent.first { it == 3 } }
                vehicle.action.pauseMission()
                // Every GLOBAL_POSITION_INT (4 Hz), not the StateFlow, which skips repeats of a vehicle standing still.
                val reports = vehicle.messages.mapNotNull { it.message as? GlobalPositionInt }.map { Location(it.lat() / 1e7, it.lon() / 1e7, (it.relativeAlt() / 1000.0).m) }
                // Reports come at 4 Hz of the vehicle's own time: settled is 2 s of them within 0.3 m, held is the next 30 s.
                val settled = withTimeout(10.minutes) {
                    val window = ArrayDeque<Location>()
                    reports.first { p ->
                        window.addLast(p)
                        if (window.size > 8) window.removeFirst()
                        window.size == 8 && window.all { it.distanceTo(p).meters < 0.3 }
                    }
                }
                val held = withTimeout(10.minutes) { reports.take(120).toList() }
                for (p in held) {
                    p.distanceTo(settled).meters shouldBeLessThan 1.0
                    abs(p.altitude.meters - settled.altitude.meters) shouldBeLessThan 0.5
                }
                vehicle.telemetry.missionCurrent.value shouldBe 3
                val (reached, recording) = recordReached(vehicle)
                vehicle.action.continueMission()
                withTimeout(20.minutes) { vehicle.telemetry.missionCurrent.first { it == 4 } }
                recording.cancel()
                reached.first() shouldBe 3
            } }
        }
    }

    "an ArduCopter goto paused by another process resumes to its destination, not into a mission it does not have" {
        virtualRun { flying(SimVehicleConfig(systemId = 34)) { vehicle, sim ->
            val home = SimVehicleConfig.DEFAULT_HOME
            Flights.keepArmedOnGround(vehicle)
            vehicle.action.setMode("GUIDED")
            vehicle.action.arm()
            vehicle.action.takeoff(15.m)
            val target = home.offset(north = 150.m, east = 0.m).copy(altitude = (home.altitude.meters + 15).m)
            vehicle.action.goto(target)
            withTimeout(2.minutes) { vehicle.telemetry.position.first { it!!.location.distanceTo(home).meters > 30 } }
            // `pod pause` ran in another process: this one has not seen it.
            vehicle.commands.send(pod.mavlink.command.VehicleCommand(MavCommands.DO_PAUSE_CONTINUE, param1 = 0f))
            vehicle.action.continueMission()
            vehicle.action.awaitArrival(target, within = 2.m, timeout = 3.minutes)
            sim.state.value.modeName shouldBe "GUIDED"
        } }
    }

    "an ArduPlane with no landing sequence on board lands at home after the approach the executor plans, not refused" {
        virtualRun { flying(SimVehicleConfig(systemId = 35, type = VehicleType.FIXED_WING)) { vehicle, _ ->
            val home = SimVehicleConfig.DEFAULT_HOME
            vehicle.action.arm()
            vehicle.action.takeoff(50.m)
            vehicle.action.land()
            vehicle.telemetry.mode.value?.name shouldBe "AUTO"
            vehicle.action.awaitLanded(timeout = 15.minutes)
            // ArduPlane floats on past the land point after its flare: on the runway, not where it was.
            vehicle.telemetry.position.value!!.location.distanceTo(home).meters shouldBeLessThan 400.0
        } }
    }
})
