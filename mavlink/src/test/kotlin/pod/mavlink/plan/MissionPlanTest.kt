package pod.mavlink.plan

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldBeSorted
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.arbitrary
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.orNull
import io.kotest.property.checkAll
import kotlin.time.Duration.Companion.seconds
import pod.core.mission.LoiterDuration
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.mission.PrecisionLand
import pod.core.mission.SpeedKind
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.units.mps
import pod.mavlink.command.MavCommands

/** Locations as the wire carries them: degrees × 10⁷, heights a float holds exactly. */
private val locations = arbitrary {
    Location(Arb.int(411_000_000..412_000_000).bind() / 1e7, Arb.int(-86_500_000..-85_500_000).bind() / 1e7, (Arb.int(2..800).bind() * 0.5).m) // at least 1 m: lower is "the current height" (MissionPlanner)
}

/** Steps that [flavor] takes as mission items and reads back unchanged. */
internal fun steps(flavor: MissionFlavor) = arbitrary {
    val at = locations.bind()
    when (Arb.int(0..9).bind()) {
        0 -> MissionStep.TakeOff(at, (if (flavor.fixedWing) Arb.int(0..30).bind() else 0).deg)
        1 -> MissionStep.Waypoint(at, Arb.int(0..60).bind().seconds)
        2 -> MissionStep.Loiter(
            at, Arb.int(-100..100).bind().m,
            when (Arb.int(0..2).bind()) {
                0 -> LoiterDuration.Unlimited
                1 -> if (flavor.isPx4) LoiterDuration.Unlimited else LoiterDuration.Turns(Arb.int(1..10).bind())
                else -> LoiterDuration.Time(Arb.int(1..120).bind().seconds)
            },
        )
        3 -> MissionStep.Land(at.copy(altitude = 0.m), Arb.int(0..359).orNull().bind()?.deg, Arb.enum<PrecisionLand>().bind())
        4 -> MissionStep.ReturnHome
        5 -> {
            val kinds = if (flavor == MissionFlavor.ARDUCOPTER) SpeedKind.entries else listOf(SpeedKind.AIR, SpeedKind.GROUND)
            MissionStep.ChangeSpeed(kinds[Arb.int(kinds.indices).bind()], (Arb.int(1..60).bind() * 0.5).mps)
        }
        6 -> if (flavor == MissionFlavor.ARDUPLANE) MissionStep.ChangeAltitude((Arb.int(0..400).bind() * 0.5).m) else MissionStep.StopCapture
        7 -> MissionStep.Delay(Arb.int(1..60).bind().seconds)
        8 -> MissionStep.StartCapture(Arb.int(0..20).bind(), Arb.int(1..10).bind().seconds)
        else -> MissionStep.StopCapture
    }
}

private val home = Location(41.178_046, -8.595_786, 120.m)

class MissionPlanTest : StringSpec({
    for (flavor in MissionFlavor.entries) {
        "a ${flavor.name} mission reads back from its items as the same steps" {
            checkAll(300, Arb.list(steps(flavor), 1..25)) { steps ->
                val plan = MissionPlanner.plan(Mission("m", null, steps), flavor, home)
                plan.keyedCommands shouldBe emptyList()
                // A plane's landing step also holds its approach waypoint, which reads back as a waypoint of its own.
                val approaches = plan.items.indices.filter { i -> plan.items[i].command == MavCommands.NAV_WAYPOINT && plan.stepOf(i)?.let { steps[it] } is MissionStep.Land }
                approaches.size shouldBe if (flavor.fixedWing) steps.count { it is MissionStep.Land } else 0
                MissionReader.steps(plan.items.filterIndexed { i, _ -> i !in approaches }, flavor) shouldBe steps
            }
        }

        "every ${flavor.name} item but home belongs to one step, in step order, and every step has items" {
            checkAll(200, Arb.list(steps(flavor), 1..25)) { steps ->
                val plan = MissionPlanner.plan(Mission("m", null, steps), flavor, home)
                plan.items.indices.map { it } shouldBe plan.items.map { it.seq }
                val mapped = plan.items.indices.drop(flavor.firstItem).map { plan.stepOf(it)!! }
                mapped.shouldBeSorted()
                mapped.toSet() shouldBe steps.indices.toSet()
                withClue("home is not a step") { plan.stepOf(0) shouldBe if (flavor.homeAtZero) null else 0 }
            }
        }
    }

    "ArduPilot's item 0 is the vehicle's home at its altitude above sea level; the mission's planned home sends no DO_SET_HOME" {
        val planned = Location(41.17, -8.59)
        val mission = Mission("m", planned, listOf(MissionStep.TakeOff(planned.copy(altitude = 10.m), 0.deg)))
        val plan = MissionPlanner.plan(mission, MissionFlavor.ARDUCOPTER, home)
        plan.items[0].frame shouldBe 0
        plan.items[0].z shouldBe home.altitude.meters.toFloat()
        plan.items[0].latitude shouldBe (home.latitude plusOrMinus 1e-7)
        plan.beforeStart shouldBe emptyList()
        MissionReader.mission("m", plan.items, MissionFlavor.ARDUCOPTER).home?.latitude shouldBe (home.latitude plusOrMinus 1e-7)
    }

    "an ArduPlane landing is preceded by an approach waypoint, not DO_LAND_START, and both items map to the landing step" {
        val a = home.copy(altitude = 40.m)
        val plan = MissionPlanner.plan(
            Mission("m", null, listOf(MissionStep.TakeOff(a, 15.deg), MissionStep.Waypoint(a), MissionStep.Land(a.copy(altitude = 0.m)))),
            MissionFlavor.ARDUPLANE, home,
        )
        plan.items.map { it.command } shouldBe listOf(16, 22, 16, 16, 21)
        plan.items.none { it.command == MavCommands.DO_LAND_START } shouldBe true
        plan.itemsOf(2) shouldBe listOf(3, 4)
        plan.items[1].param1 shouldBe 15f
        plan.items[4].param4.isNaN() shouldBe true
    }

    "a fixed-wing landing glides about 5° from an approach point into the landing direction, even from a waypoint over the land point" {
        val land = home.offset(north = 500.m, east = 0.m).copy(altitude = 0.m)
        // returnHomeAndLand's shape: out north, back over the land point at height, land there.
        val steps = listOf(
            MissionStep.TakeOff(home.copy(altitude = 40.m), 15.deg),
            MissionStep.Waypoint(land.offset(north = 900.m, east = 0.m).copy(altitude = 80.m)),
            MissionStep.Waypoint(land.copy(altitude = 80.m)),
            MissionStep.Land(land),
        )
        for (flavor in listOf(MissionFlavor.ARDUPLANE, MissionFlavor.PX4_FIXED_WING)) {
            val plan = MissionPlanner.plan(Mission("m", null, steps), flavor, home)
            val (approach, touchdown) = plan.itemsOf(3).map { plan.items[it] }
            touchdown.command shouldBe MavCommands.NAV_LAND
            val from = Location(approach.latitude, approach.longitude)
            val distance = from.distanceTo(Location(touchdown.latitude, touchdown.longitude)).meters
            val glide = Math.toDegrees(kotlin.math.atan(approach.z / distance))
            glide shouldBe (LandingApproach.GLIDE_DEGREES plusOrMinus 0.2)
            approach.z shouldBe LandingApproach.APPROACH_HEIGHT.meters.toFloat()
            // The plane came south over the land point: it lands heading south, from the north.
            (approach.latitude > touchdown.latitude) shouldBe true
        }
    }

    "PX4 flies loiter turns as a timed loiter, since it refuses NAV_LOITER_TURNS" {
        val plan = MissionPlanner.plan(Mission("m", null, listOf(MissionStep.Loiter(home, 20.m, LoiterDuration.Turns(3)))), MissionFlavor.PX4, home)
        val item = plan.items.single()
        item.command shouldBe MavCommands.NAV_LOITER_TIME
        item.param1 shouldBe (maxOf(2 * Math.PI * 20 / MissionPlanner.LOITER_TURN_SPEED_MPS, MissionPlanner.MIN_SECONDS_PER_TURN) * 3).toFloat()
        item.param3 shouldBe 20f
    }

    "a change of altitude is a waypoint over the previous point on ArduCopter and PX4, NAV_CONTINUE_AND_CHANGE_ALT on ArduPlane" {
        val a = home.offset(30.m, 0.m, 20.m).copy(altitude = 20.m)
        val steps = listOf(MissionStep.TakeOff(a, 0.deg), MissionStep.ChangeAltitude(35.m))
        for (flavor in listOf(MissionFlavor.ARDUCOPTER, MissionFlavor.PX4)) {
            val wp = MissionReader.steps(MissionPlanner.plan(Mission("m", null, steps), flavor, home).items, flavor)[1] as MissionStep.Waypoint
            (wp.location.distanceTo(a).meters < 0.02) shouldBe true
            wp.location.altitude shouldBe 35.m
        }
        val plane = MissionPlanner.plan(Mission("m", null, steps), MissionFlavor.ARDUPLANE, home).items.last()
        plane.command shouldBe MavCommands.NAV_CONTINUE_AND_CHANGE_ALT
        plane.z shouldBe 35f
    }

    "a climb rate is a command keyed to the next item on PX4 and ArduPlane, a mission item on ArduCopter" {
        val steps = listOf(MissionStep.TakeOff(home.copy(altitude = 10.m), 0.deg), MissionStep.ChangeSpeed(SpeedKind.CLIMB, 3.mps), MissionStep.Waypoint(home.copy(altitude = 10.m)), MissionStep.ChangeSpeed(SpeedKind.DESCENT, 1.mps))
        val px4 = MissionPlanner.plan(Mission("m", null, steps), MissionFlavor.PX4, home)
        px4.items.map { it.command } shouldBe listOf(22, 16)
        px4.keyedCommands.map { Triple(it.seq, it.step, it.command.param1) } shouldBe listOf(Triple(1, 1, 2f), Triple(2, 3, 3f))
        px4.itemsOf(1) shouldBe emptyList()
        val copter = MissionPlanner.plan(Mission("m", null, steps), MissionFlavor.ARDUCOPTER, home)
        copter.keyedCommands shouldBe emptyList()
        copter.items.map { it.command } shouldBe listOf(16, 22, 178, 16, 178)
    }
})
