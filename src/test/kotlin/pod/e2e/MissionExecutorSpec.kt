package pod.e2e

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlin.math.abs
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.mapNotNull
import kotlinx.coroutines.flow.take
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.mission.LoiterDuration
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.mission.PrecisionLand
import pod.core.mission.SpeedKind
import pod.core.platform.MissionEvent
import pod.core.platform.SafeState
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.units.mps
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleLost
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.MavCommands
import pod.mavlink.plan.MissionFlavor
import pod.mavlink.plan.MissionPlanner
import pod.mavlink.plan.MissionReader
import pod.sim.SimFlavor

/** Takeoff, two waypoints, a loiter of one turn, and a landing back home. */
private fun copterSurvey(home: Location) = Mission(
    "survey", null,
    listOf(
        MissionStep.TakeOff(home.at(0, 0, 15.0), 0.deg),
        MissionStep.Waypoint(home.at(30, 0, 15.0)),
        MissionStep.Waypoint(home.at(30, 30, 20.0)),
        MissionStep.Loiter(home.at(30, 30, 20.0), 10.m, LoiterDuration.Turns(1)),
        MissionStep.Land(home.at(0, 0, 0.0)),
    ),
)

private fun planeCircuit(home: Location) = Mission(
    "circuit", null,
    listOf(
        MissionStep.TakeOff(home.at(0, 0, 40.0), 15.deg),
        MissionStep.Waypoint(home.at(0, 500, 60.0)),
        MissionStep.Waypoint(home.at(600, 500, 60.0)),
        MissionStep.Loiter(home.at(900, 0, 50.0), 80.m, LoiterDuration.Turns(1)),
        MissionStep.Waypoint(home.at(500, 0, 30.0)),
        MissionStep.Land(home.at(0, 0, 0.0)),
    ),
)

/** Uploaded, started, each step started and done in order, completed. */
private fun inOrder(steps: Int): List<MissionEvent> = listOf(MissionEvent.Uploaded(steps), MissionEvent.Started) +
    (0 until steps).flatMap { listOf(MissionEvent.StepStarted(it), MissionEvent.StepDone(it)) } + MissionEvent.Completed

class MissionExecutorSpec : StringSpec({

    for (flavor in listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4, SimFlavor.ARDUPLANE)) {
        "a ${flavor.name} flies takeoff, waypoints, a loiter of turns and a landing to completion: landed, disarmed, every step reported in order" {
            virtualRun { withVehicle(flavor) { fleet, v, vehicle, sim ->
                val home = sim.config.home
                val mission = if (flavor == SimFlavor.ARDUPLANE) planeCircuit(home) else copterSurvey(home)
                val events = ArrayList<MissionEvent>()
                withTimeout(1.hours) { fleet.fly(v, mission).collect { events += it } }
                events.filter { it !is MissionEvent.Prepared } shouldBe inOrder(mission.steps.size)
                // Got ready on the ground in the order it was done, and said so: the mode first, then armed.
                events.filterIsInstance<MissionEvent.Prepared>().single().changes shouldBe when (flavor) {
                    SimFlavor.ARDUCOPTER -> listOf("mode STABILIZE → GUIDED", "armed")
                    SimFlavor.ARDUPLANE -> listOf("mode MANUAL → LOITER", "armed")
                    else -> listOf("armed")
                }
                vehicle.telemetry.armed.value shouldBe false
                vehicle.telemetry.landedState.value shouldBe LandedState.ON_GROUND
                vehicle.telemetry.position.value!!.location.distanceTo(home).meters shouldBeLessThan (if (flavor == SimFlavor.ARDUPLANE) 100.0 else 3.0)
                val items = sim.missionServer.list(pod.mavlink.mission.MissionType.MISSION).size
                when (flavor) {
                    SimFlavor.ARDUPLANE -> sim.reachedItems.value.last() shouldBe items - 1
                    // ArduCopter reports no final NAV_LAND reached and goes back to item 1 once disarmed:
                    // completion came from MISSION_CURRENT (asked for) and landed + disarmed.
                    SimFlavor.ARDUCOPTER -> {
                        sim.reachedItems.value.last() shouldBe items - 2
                        sim.missionServer.current shouldBe 1
                    }
                    else -> Unit
                }
            } }
        }
    }

    for (flavor in listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4)) {
        "a ${flavor.name} mission ending in an unlimited loiter reports loitering once the vehicle is at the final point, and never completes by itself" {
            virtualRun { withVehicle(flavor) { fleet, v, vehicle, sim ->
                val home = sim.config.home
                val end = home.at(30, 30, 20.0)
                val mission = Mission("loiter", null, listOf(MissionStep.TakeOff(home.at(0, 0, 15.0), 0.deg), MissionStep.Waypoint(home.at(30, 0, 15.0)), MissionStep.Loiter(end, 0.m, LoiterDuration.Unlimited)))
                val events = ArrayList<MissionEvent>()
                withTimeout(20.minutes) { fleet.flyUntilLoitering(v, mission) { events += it } }
                events.filter { it !is MissionEvent.Prepared } shouldBe inOrder(3).dropLast(2) + MissionEvent.Loitering(2)
                val p = vehicle.telemetry.position.value!!
                p.location.distanceTo(end).meters shouldBeLessThan 3.0
                abs(p.relativeAltitude.meters - 20.0) shouldBeLessThan 3.0
                vehicle.telemetry.armed.value shouldBe true
                vehicle.telemetry.mode.value!!.name shouldBe if (flavor == SimFlavor.PX4) "AUTO.MISSION" else "AUTO"
            } }
        }
    }

    for (flavor in listOf(SimFlavor.ARDUCOPTER, SimFlavor.PX4, SimFlavor.ARDUPLANE)) {
        "a ${flavor.name} mission downloaded from the vehicle reads back as the same steps" {
            virtualRun { withVehicle(flavor) { _, _, vehicle, sim ->
                val home = sim.config.home
                val missionFlavor = MissionFlavor.of(vehicle.identity.value)
                val plane = flavor == SimFlavor.ARDUPLANE
                val steps = listOf(
                    MissionStep.TakeOff(home.at(0, 0, 30.0), (if (plane) 12 else 0).deg),
                    MissionStep.ChangeSpeed(SpeedKind.GROUND, 6.5.mps),
                    MissionStep.Waypoint(home.at(40, 10, 30.0), 5.seconds),
                    MissionStep.StartCapture(0, 2.seconds),
                    MissionStep.Loiter(home.at(60, 10, 35.0), (-25).m, if (flavor == SimFlavor.PX4) LoiterDuration.Time(20.seconds) else LoiterDuration.Turns(2)),
                    MissionStep.StopCapture,
                    MissionStep.Delay(3.seconds),
                    MissionStep.Land(home.at(0, 0, 0.0), 90.deg, PrecisionLand.OPPORTUNISTIC),
                )
                vehicle.mission.upload(MissionPlanner.plan(Mission("m", null, steps), missionFlavor, home).items)
                // ArduPilot keeps its own form of each item (AP_Mission::mission_cmd_to_mavlink_int): a
                // landing comes back with param4 ±1 (a direction, not the yaw) and no precision mode, and
                // an ArduPlane waypoint without its hold time. Compare what it keeps.
                fun kept(all: List<MissionStep>) = if (flavor == SimFlavor.PX4) all else all.map { step ->
                    when {
                        step is MissionStep.Land -> step.copy(yaw = null, precision = PrecisionLand.DISABLED)
                        step is MissionStep.Waypoint && plane -> step.copy(hold = kotlin.time.Duration.ZERO)
                        else -> step
                    }
                }
                val read = kept(MissionReader.steps(vehicle.mission.download(), missionFlavor))
                if (plane) {
                    // The planner puts an approach waypoint before a plane's landing; it reads back as the waypoint it is.
                    (read[read.size - 2] is MissionStep.Waypoint) shouldBe true
                    read.filterIndexed { i, _ -> i != read.size - 2 } shouldBe kept(steps)
                } else {
                    read shouldBe kept(steps)
                }
            } }
        }
    }

    "cancelling a flight mid-mission returns promptly, and HOLD then keeps the copter where it stopped, at its height, armed, in BRAKE" {
        virtualRun { withVehicle(SimFlavor.ARDUCOPTER) { fleet, v, vehicle, sim ->
            val home = sim.config.home
            val mission = Mission("long", null, listOf(MissionStep.TakeOff(home.at(0, 0, 15.0), 0.deg), MissionStep.Waypoint(home.at(300, 0, 15.0)), MissionStep.Land(home.at(0, 0, 0.0))))
            val events = MutableStateFlow<List<MissionEvent>>(emptyList())
            val flight = launch { fleet.fly(v, mission).collect { e -> events.value += e } }
            withTimeout(10.minutes) { events.first { MissionEvent.StepStarted(1) in it } }
            withTimeout(1.seconds) { flight.cancelAndJoin() }
            withTimeout(10.seconds) { fleet.makeSafe(v, SafeState.HOLD) }
            val stopped = vehicle.telemetry.position.value!!.location
            val stoppedHeight = vehicle.telemetry.position.value!!.relativeAltitude.meters
            // Every GLOBAL_POSITION_INT, not the StateFlow, which skips repeats of a vehicle standing still.
            val reports = vehicle.messages.mapNotNull { it.message as? GlobalPositionInt }.map { Location(it.lat() / 1e7, it.lon() / 1e7, (it.relativeAlt() / 1000.0).m) }
            // Reports come at 4 Hz of the vehicle's own time: settled is 2 s of them within 0.2 m, held is the next 10 s.
            val settled = withTimeout(2.minutes) {
                val window = ArrayDeque<Location>()
                reports.first { p ->
                    window.addLast(p)
                    if (window.size > 8) window.removeFirst()
                    window.size == 8 && window.all { it.distanceTo(p).meters < 0.2 }
                }
            }
            settled.distanceTo(stopped).meters shouldBeLessThan 20.0
            // ArduCopter's LOITER (Pod's hold before) sinks at PILOT_SPEED_UP with no stick input.
            abs(settled.altitude.meters - stoppedHeight) shouldBeLessThan 1.0 // the reports carry the height above home
            for (p in withTimeout(2.minutes) { reports.take(40).toList() }) {
                p.distanceTo(settled).meters shouldBeLessThan 1.0
                abs(p.altitude.meters - settled.altitude.meters) shouldBeLessThan 0.5
            }
            vehicle.telemetry.armed.value shouldBe true
            vehicle.telemetry.mode.value!!.name shouldBe "BRAKE"
            events.value shouldContain MissionEvent.Started
        } }
    }

    "RETURN_HOME after a cancelled flight switches to RTL and the copter lands at home" {
        virtualRun { withVehicle(SimFlavor.ARDUCOPTER) { fleet, v, vehicle, sim ->
            val home = sim.config.home
            val mission = Mission("long", null, listOf(MissionStep.TakeOff(home.at(0, 0, 15.0), 0.deg), MissionStep.Waypoint(home.at(300, 0, 15.0)), MissionStep.Land(home.at(0, 0, 0.0))))
            val started = CompletableDeferred<Unit>()
            val flight = launch { fleet.fly(v, mission).collect { if (it == MissionEvent.StepStarted(1)) started.complete(Unit) } }
            withTimeout(10.minutes) { started.await() }
            withTimeout(1.seconds) { flight.cancelAndJoin() }
            withTimeout(2.seconds) { fleet.makeSafe(v, SafeState.RETURN_HOME) }
            vehicle.telemetry.mode.value!!.name shouldBe "RTL"
            vehicle.action.awaitLanded(timeout = 20.minutes)
            vehicle.telemetry.position.value!!.location.distanceTo(home).meters shouldBeLessThan 3.0
        } }
    }

    "a vehicle whose simulator stops mid-mission fails the flight with VehicleLost" {
        virtualRun { withVehicle(SimFlavor.ARDUCOPTER) { fleet, v, _, sim ->
            val home = sim.config.home
            val mission = Mission("lost", null, listOf(MissionStep.TakeOff(home.at(0, 0, 15.0), 0.deg), MissionStep.Waypoint(home.at(300, 0, 15.0)), MissionStep.Land(home.at(0, 0, 0.0))))
            val outcome = CompletableDeferred<Throwable?>()
            val flight = launch {
                outcome.complete(runCatching { fleet.fly(v, mission).collect { if (it == MissionEvent.StepStarted(1)) sim.stop() } }.exceptionOrNull())
            }
            val error = withTimeout(5.minutes) { outcome.await() }
            flight.join()
            (error is VehicleLost) shouldBe true
            (error as VehicleLost).systemId shouldBe v.id
        } }
    }

    "a refused arm fails the flight with CommandRejected carrying the autopilot's reason" {
        virtualRun { withVehicle(SimFlavor.ARDUCOPTER) { fleet, v, vehicle, sim ->
            vehicle.params.write("BATT_ARM_VOLT", 99.0)
            val home = sim.config.home
            val mission = Mission("refused", null, listOf(MissionStep.TakeOff(home.at(0, 0, 15.0), 0.deg), MissionStep.Land(home.at(0, 0, 0.0))))
            val events = ArrayList<MissionEvent>()
            val e = shouldThrow<CommandRejected> { withTimeout(10.minutes) { fleet.fly(v, mission).collect { events += it } } }
            e.command.command shouldBe MavCommands.COMPONENT_ARM_DISARM
            e.statusTexts.joinToString() shouldContain "Battery"
            events shouldBe listOf(MissionEvent.Uploaded(2))
            vehicle.telemetry.armed.value shouldBe false
        } }
    }
})
