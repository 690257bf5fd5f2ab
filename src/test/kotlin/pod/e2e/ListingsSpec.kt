package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.ints.shouldBeGreaterThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.engine.EngineEvent
import pod.core.engine.PickTimeout
import pod.core.platform.MissionEvent
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType
import pod.core.platform.PlatformVehicle
import pod.core.units.m
import pod.core.vehicle.VehicleLost
import pod.dsl.ignore
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.dsl.then
import pod.dsl.watch
import pod.mavlink.executor.MissionNotFlyable
import pod.samples.listing1
import pod.samples.listing2
import pod.samples.listing3
import pod.samples.listing4
import pod.sim.SimFlavor
import kotlin.math.abs
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

private fun copters(n: Int) = List(n) { SimFlavor.ARDUCOPTER }

/** A short hop: take off, 40 m north, land back home. */
private fun surveyFrom(v: PlatformVehicle) = mission("hop ${v.name}") {
    home(v.home.value!!)
    takeOff(20.m)
    move(north = 40.m)
    returnHomeAndLand()
}

/** For each survey flight: (vehicle, start, end) in vehicle time, from the engine's events. */
private fun surveyFlights(events: List<EngineEvent>): List<Triple<Int, Duration, Duration>> {
    val ends = events.mapNotNull {
        when (it) {
            is EngineEvent.TaskCompleted -> it.id to it.at
            is EngineEvent.TaskCancelled -> it.id to it.at
            is EngineEvent.TaskFailed -> it.id to it.at
            else -> null
        }
    }.toMap()
    return events.filterIsInstance<EngineEvent.Flying>().filter { it.mission.name.startsWith("survey") }
        .map { Triple(it.vehicle, it.at, ends.getValue(it.task)) }
}

class ListingsSpec : StringSpec({
    "Listing 2: the vehicle surveys until its battery is low, then comes home and lands instead of finishing" {
        virtualRun { listing2Run() }
    }

    "Listing 3: two vehicles fly their surveys at the same time and both land back home" {
        virtualRun {
            val (vehicles, record) = simulate(copters(2)) { listing3() }
            val flights = surveyFlights(record.events)
            flights.map { it.first }.toSet() shouldBe vehicles.ids
            val (a, b) = flights
            (a.second < b.third && b.second < a.third) shouldBe true // the two flights overlap in time
            record.events.filterIsInstance<EngineEvent.Mission>().count { it.event == MissionEvent.Completed } shouldBe 2
            vehicles.forEach { it.landedState.value shouldBe LandedState.ON_GROUND }
        }
    }

    "Listing 1: three camera vehicles survey three areas at once" {
        virtualRun {
            val (vehicles, record) = simulate(copters(3)) { listing1() }
            vehicles.size shouldBe 3
            record.events.filterIsInstance<EngineEvent.Mission>().count { it.event == MissionEvent.Completed } shouldBe 3
            val flights = surveyFlights(record.events)
            flights.maxOf { it.second } shouldBeLess flights.minOf { it.third }
        }
    }

    "Listing 4: whenever a charged replacement exists, two vehicles are on survey (30 minutes of vehicle time)" {
        virtualRun { listing4Run(30.minutes) }
    }

    "each listing run twice with the same seed gives the same events at the same times" {
        for (run in listOf<suspend VirtualFleet.() -> List<EngineEvent>>(
            { simulate(copters(3)) { listing1() }.second.events },
            { listing2Run() },
            { simulate(copters(2)) { listing3() }.second.events },
            { listing4Run(20.minutes) },
        )) {
            val first = traceOf(seed = 5, run)
            val second = traceOf(seed = 5, run)
            second shouldBe first
            first.size shouldBeGreaterThanOrEqual 10
        }
    }

    "cancelling a program leaves every airborne vehicle holding within 2 s" {
        virtualRun {
            simulate(copters(2)) { sim ->
                coroutineScope {
                    val program = launch { listing3() }
                    val mav = sim.vehicles.value.map { sim.platform.mavlink(it) }
                    withTimeout(2.minutes) {
                        mav.forEach { v -> v.telemetry.position.first { (it?.relativeAltitude?.meters ?: 0.0) > 10.0 } }
                    }
                    withTimeout(2.seconds) {
                        program.cancelAndJoin()
                        mav.forEach { v -> v.telemetry.mode.first { it?.name == "BRAKE" } }
                    }
                    mav.forEach { it.telemetry.landedState.value shouldBe LandedState.IN_AIR }
                    // Settled in the air: ArduCopter's LOITER with no stick input would sink at 2.5 m/s to the ground.
                    withTimeout(1.minutes) {
                        mav.forEach { v ->
                            v.telemetry.position.first { p -> p != null && abs(p.velocityDown.metersPerSecond) < 0.2 && p.relativeAltitude.meters > 10.0 }
                        }
                    }
                }
            }
        }
    }

    "a vehicle that stops sending heartbeats fails its task, and the program, with VehicleLost" {
        virtualRun {
            val lost = shouldThrow<VehicleLost> {
                simulate(copters(1)) { sim ->
                    val v = pick { count(1) }[0]
                    coroutineScope {
                        launch {
                            sim.platform.mavlink(v).telemetry.position.first { (it?.relativeAltitude?.meters ?: 0.0) > 10.0 }
                            sim[v.id].stop()
                        }
                        execute(surveyFrom(v) on v)
                    }
                }
            }
            lost.systemId shouldBe 1
        }
    }

    "watch … onError ignore lets a program go on past a mission the autopilot cannot fly" {
        virtualRun {
            val (_, record) = simulate(copters(1)) {
                val v = pick { count(1) }[0]
                val home = v.home.value!!
                val noTakeOff = mission("no take-off") { home(home); goPos(home.latitude, home.longitude, 20.m) }
                execute((watch(noTakeOff on v) onError ignore) then (surveyFrom(v) on v))
            }
            val failed = record.events.filterIsInstance<EngineEvent.TaskFailed>().single { it.label == "no take-off" }
            (failed.error is MissionNotFlyable) shouldBe true
            record.events.filterIsInstance<EngineEvent.Mission>().count { it.event == MissionEvent.Completed } shouldBe 1
        }
    }

    "a pick that can never be met fails after its timeout naming what it asked for" {
        virtualRun {
            val error = shouldThrow<PickTimeout> {
                simulate(copters(2)) { pick { count(2); type(VehicleType.FIXED_WING); timeout(20.seconds) } }
            }
            error.message!! shouldContain "2 vehicles of type FIXED_WING"
        }
    }
})

/** Listing 2 at a low-battery threshold of 85 %, checked; its events. */
private suspend fun VirtualFleet.listing2Run(): List<EngineEvent> {
    val (v, record) = simulate(copters(1)) { sim ->
        val v = listing2(lowBattery = 0.85)
        val mav = sim.platform.mavlink(v)
        withTimeout(10.minutes) { mav.telemetry.armed.first { !it } }
        v
    }
    val surveys = record.events.filterIsInstance<EngineEvent.Flying>().filter { it.mission.name.startsWith("survey") }
    surveys.size shouldBe 1
    val surveyTask = surveys.single().task
    record.events.filterIsInstance<EngineEvent.TaskCancelled>().map { it.id } shouldContainAll listOf(surveyTask)
    record.events.filterIsInstance<EngineEvent.Mission>().filter { it.task == surveyTask }.map { it.event } shouldContainAll listOf(MissionEvent.Started)
    record.events.filterIsInstance<EngineEvent.Mission>().filter { it.task == surveyTask }.map { it.event }.contains(MissionEvent.Completed) shouldBe false
    val landing = record.events.filterIsInstance<EngineEvent.Flying>().single { it.mission.name.startsWith("land") }
    record.events.filterIsInstance<EngineEvent.Mission>().filter { it.task == landing.task }.map { it.event } shouldContainAll listOf(MissionEvent.Completed)
    v.landedState.value shouldBe LandedState.ON_GROUND
    (v.battery.value!!.remaining!!) shouldBeLessThan 0.85
    v.home.value!!.distanceTo(v.position.value!!.location).meters shouldBeLessThan 5.0
    return record.events
}

/** Listing 4 for [length] on four copters, checked: two on survey whenever one can be; its events. */
private suspend fun VirtualFleet.listing4Run(length: Duration): List<EngineEvent> {
    val (_, record) = simulate(copters(4)) { listing4(duration = length) }
    val flights = surveyFlights(record.events)
    flights.map { it.first }.toSet() shouldBe setOf(1, 2, 3, 4) // the tired pair was replaced
    val twoUp = flights.sortedBy { it.second }[1].second
    val end = flights.maxOf { it.third }
    // Sample every vehicle-second from when both slots first fly to the end of `during`:
    // exactly two survey flights run, except within a few seconds of one ending (handover).
    val gaps = generateSequence(twoUp) { it + 1.seconds }.takeWhile { it < end - 1.seconds }.filter { t ->
        val running = flights.count { t >= it.second && t < it.third }
        running != 2 && flights.none { t >= it.third && t - it.third < 10.seconds }
    }.toList()
    gaps.shouldBeEmpty()
    record.events.filterIsInstance<EngineEvent.Message>().map { it.text }.filter { "takes over" in it }.size shouldBeGreaterThanOrEqual 2
    return record.events
}

/** The events of [run] in a fresh virtual world seeded with [seed], as lines. */
private fun traceOf(seed: Long, run: suspend VirtualFleet.() -> List<EngineEvent>): List<String> {
    var trace: List<String> = emptyList()
    virtualRun(seed) { trace = run().trace() }
    return trace
}

private infix fun Duration.shouldBeLess(other: Duration) {
    (this < other) shouldBe true
}
