package pod.test

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldHaveAtLeastSize
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.should
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.RandomSource
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import pod.core.engine.EngineEvent
import pod.core.engine.Program
import pod.core.platform.PlatformVehicle
import pod.core.units.m
import pod.core.vehicle.VehicleType
import pod.dsl.concurrently
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.sim.fault.LinkFaults
import kotlin.time.Duration.Companion.milliseconds

/**
 * Programs on virtual fleets: a flight over a link losing 20 % lands where it should and the
 * record shows the loss; a seed gives the same run twice; runs nest inside `checkAll`.
 */
class VirtualFleetTest : StringSpec({

    "a copter flies out and back over a link losing 20 % each way: it keeps to its line and its height, lands at home, and the record shows the loss" {
        val record = virtualFleet(seed = 11) { copters(1); loss(20.percent) }.run { outAndBack() }
        val track = record.track(1)
        track should landWithin(2.m, of = track.home)
        track should neverBelow(15.m, fartherThan = 10.m)
        track should stayInCorridor(track.home, track.home.offset(60.m, 0.m), width = 6.m)
        // Out along the leg, from 15 m to 45 m north: level at its 20 m.
        val leg = track.points.filter { it.north.meters in 15.0..45.0 }.let { it.first().at..it.last().at }
        track should holdAltitude(20.m, tolerance = 1.5.m, during = leg)
        record.events.filterIsInstance<EngineEvent.TaskFailed>() shouldBe emptyList()
        record.events.filterIsInstance<EngineEvent.TaskCompleted>().map { it.label } shouldContain "out and back on [copter-1]"
        record.towardsStation.dropped shouldBeGreaterThan 10
        record.towardsVehicles.dropped shouldBeGreaterThan 10
        (record.events.last().at <= record.duration) shouldBe true
    }

    "the issue's fleet, three copters, a plane and a PX4 copter over a link losing 20 %, flies one program: every copter lands home, the plane lands near it" {
        val record = virtualFleet(seed = 29) { copters(3); plane(1); px4(1); loss(20.percent) }.run {
            val all = pick { count(5) }.toList()
            execute(concurrently(all.map { v -> if (v.type == VehicleType.FIXED_WING) circuit(v) on v else hop(v) on v }))
        }
        record.events.filterIsInstance<EngineEvent.TaskFailed>() shouldBe emptyList()
        record.tracks.keys shouldBe setOf(1, 2, 3, 4, 5)
        for (id in listOf(1, 2, 3, 5)) record.track(id) should landWithin(2.m, of = record.track(id).home)
        // A plane lands along its approach, beyond the point it aims at.
        record.track(4) should landWithin(80.m, of = record.track(4).home)
        record.track(4) should neverBelow(25.m, fartherThan = 300.m)
    }

    "the same seed gives the same events at the same virtual times and the same tracks; another seed, with loss on, does not" {
        val fleet = virtualFleet(seed = 5) { copters(1); px4(1); loss(20.percent) }
        val first = fleet.run { outAndBack(vehicles = 2) }
        val again = fleet.run { outAndBack(vehicles = 2) }
        first.trace shouldHaveAtLeastSize 6
        again.trace shouldBe first.trace
        again.tracks.mapValues { it.value.points } shouldBe first.tracks.mapValues { it.value.points }
        val other = fleet.withSeed(6).run { outAndBack(vehicles = 2) }
        other.trace shouldNotBe first.trace
    }

    "runs nest inside checkAll: any DSL mission over any link faults within bounds is flown to its end and lands near home" {
        val bound = LinkFaults(drop = 0.2, duplicate = 0.02, reorder = 0.02, delay = 10.milliseconds, jitter = 5.milliseconds)
        checkAll(PropTestConfig(iterations = 2, seed = 3), Arb.linkFaults(bound), Arb.long()) { faults, missionSeed ->
            val record = virtualFleet(seed = missionSeed) { copters(1); faults(faults) }.run {
                val v = pick { count(1) }[0]
                val flown = Arb.mission(v.home.value!!, radius = 80.m, legs = 1..3).sample(RandomSource.seeded(missionSeed)).value
                execute(flown on v)
                flown
            }
            withClue("$faults\n${record.result}") {
                record.events.filterIsInstance<EngineEvent.TaskFailed>() shouldBe emptyList()
                record.events.filterIsInstance<EngineEvent.TaskCompleted>().map { it.label } shouldContain "arbitrary mission on [copter-1]"
                record.track(1) should landWithin(5.m, of = record.track(1).home)
            }
        }
    }
})

/** Each of the first [vehicles] picked flies 60 m north at 20 m and lands back home, all at once. */
private suspend fun Program.outAndBack(vehicles: Int = 1) {
    val picked = pick { count(vehicles) }
    val tasks = picked.map { v ->
        mission("out and back" + if (vehicles > 1) " ${v.id}" else "") {
            home(v.home.value!!)
            takeOff(20.m)
            move(north = 60.m)
            returnHomeAndLand()
        } on v
    }
    execute(if (tasks.size == 1) tasks.single() else concurrently(tasks))
}

/** A copter's hop: up 15 m, 40 m north, back down home. */
private fun hop(v: PlatformVehicle) = mission("hop ${v.name}") {
    home(v.home.value!!)
    takeOff(15.m)
    move(north = 40.m)
    returnHomeAndLand()
}

/** A plane's circuit: take off, fly 500 m out climbing 20 m, come back over home and land. */
private fun circuit(v: PlatformVehicle) = mission("circuit ${v.name}") {
    home(v.home.value!!)
    takeOff(40.m)
    move(north = 500.m, up = 20.m)
    returnHomeAndLand()
}
