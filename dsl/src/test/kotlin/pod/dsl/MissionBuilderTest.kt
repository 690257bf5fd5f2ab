package pod.dsl

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import pod.core.mission.LoiterDuration
import pod.core.mission.MissionCompletion
import pod.core.mission.MissionStep
import pod.core.mission.PrecisionLand
import pod.core.mission.SpeedKind
import pod.core.mission.SurveyDirection
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.units.mps
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

internal val porto = Location(41.178, -8.596)

/** A mission that starts at [porto] on the ground and then runs [commands]. */
internal fun fromPorto(commands: MissionBuilder.() -> Unit) = mission {
    home(porto)
    commands()
}

internal fun Location.shouldBeNear(expected: Location, tolerance: Double = 0.01) {
    distanceTo(expected).meters shouldBe (0.0 plusOrMinus tolerance)
    altitude.meters shouldBe (expected.altitude.meters plusOrMinus 1e-6)
}

class MissionBuilderTest : StringSpec({

    "home sets the mission's home and puts the vehicle on the ground there" {
        val mission = mission {
            home(41.178, -8.596, 120.m)
            takeOff(10.m)
        }
        mission.home shouldBe Location(41.178, -8.596, 120.m)
        mission.steps.single() shouldBe MissionStep.TakeOff(porto.copy(altitude = 10.m), 15.deg)
    }

    "name and the mission argument name the mission" {
        mission("survey") { goPos(porto) }.name shouldBe "survey"
        mission { name("patrol"); goPos(porto) }.name shouldBe "patrol"
        mission { goPos(porto) }.name shouldBe "mission"
    }

    "goPos flies to a location given either way" {
        mission { goPos(porto.copy(altitude = 40.m)); goPos(41.0, -8.0, 20.m) }.steps shouldBe listOf(
            MissionStep.Waypoint(porto.copy(altitude = 40.m)),
            MissionStep.Waypoint(Location(41.0, -8.0, 20.m)),
        )
    }

    "takeOff climbs at home with the given pitch" {
        fromPorto { takeOff(30.m, pitch = 20.deg) }.steps.single() shouldBe MissionStep.TakeOff(porto.copy(altitude = 30.m), 20.deg)
    }

    "a move after takeOff starts at the takeoff height, not at home (the Dolphin plugin's bug)" {
        val move = fromPorto { takeOff(30.m); move(up = 50.m) }.steps.last()
        move shouldBe MissionStep.Waypoint(porto.copy(altitude = 80.m))
    }

    "move goes north, east and up from the current position, and the next move starts there" {
        val steps = fromPorto { takeOff(30.m); move(north = 100.m); move(east = -50.m, up = -10.m) }.steps
        steps[1].shouldBeInstanceOf<MissionStep.Waypoint>().location.shouldBeNear(porto.offset(100.m, 0.m, 30.m))
        steps[2].shouldBeInstanceOf<MissionStep.Waypoint>().location.shouldBeNear(porto.offset(100.m, (-50).m, 20.m))
    }

    "moveFromHome measures from home wherever the vehicle is" {
        val step = fromPorto { takeOff(30.m); move(north = 500.m); moveFromHome(east = 100.m, up = 40.m) }.steps.last()
        step.shouldBeInstanceOf<MissionStep.Waypoint>().location.shouldBeNear(porto.offset(0.m, 100.m, 40.m))
    }

    "moveAndLoiter commands circle the point reached by the move, 15 m radius by default" {
        val steps = fromPorto {
            takeOff(20.m)
            moveAndLoiterTurns(north = 100.m, turns = 3)
            moveAndLoiterTime(east = 100.m, time = 2.minutes, radius = 40.m)
            moveAndLoiterPos(up = 10.m)
        }.steps.drop(1).map { it.shouldBeInstanceOf<MissionStep.Loiter>() }
        steps.map { it.duration } shouldBe listOf(LoiterDuration.Turns(3), LoiterDuration.Time(2.minutes), LoiterDuration.Unlimited)
        steps.map { it.radius } shouldBe listOf(15.m, 40.m, 15.m)
        steps[2].location.shouldBeNear(porto.offset(100.m, 100.m, 30.m))
    }

    "moveAndLoiter FromHome variants circle a point measured from home" {
        val steps = fromPorto {
            takeOff(20.m)
            move(north = 900.m)
            moveAndLoiterTurnsFromHome(north = 10.m, up = 30.m, turns = 2)
            moveAndLoiterTimeFromHome(east = 10.m, up = 30.m, time = 30.seconds)
            moveAndLoiterPosFromHome(up = 50.m, radius = 25.m)
        }.steps.drop(2).map { it.shouldBeInstanceOf<MissionStep.Loiter>() }
        steps.map { it.duration } shouldBe listOf(LoiterDuration.Turns(2), LoiterDuration.Time(30.seconds), LoiterDuration.Unlimited)
        steps[0].location.shouldBeNear(porto.offset(10.m, 0.m, 30.m))
        steps[1].location.shouldBeNear(porto.offset(0.m, 10.m, 30.m))
        steps[2].location.shouldBeNear(porto.copy(altitude = 50.m))
        steps[2].radius shouldBe 25.m
    }

    "loiter commands circle a location given either way" {
        val at = Location(41.0, -8.0, 60.m)
        mission {
            loiterTurns(at, turns = 4)
            loiterTime(41.0, -8.0, 60.m, time = 1.minutes, radius = 30.m)
            loiterPos(at)
            loiterPos(41.0, -8.0, 60.m, radius = 20.m)
        }.steps shouldBe listOf(
            MissionStep.Loiter(at, 15.m, LoiterDuration.Turns(4)),
            MissionStep.Loiter(at, 30.m, LoiterDuration.Time(1.minutes)),
            MissionStep.Loiter(at, 15.m, LoiterDuration.Unlimited),
            MissionStep.Loiter(at, 20.m, LoiterDuration.Unlimited),
        )
    }

    "landingPoint lands on the ground there, keeping the heading unless a yaw is given" {
        val steps = mission {
            landingPoint(porto.copy(altitude = 30.m))
            landingPoint(41.0, -8.0, yaw = 90.deg, precisionLand = PrecisionLand.REQUIRED)
            move(up = 10.m)
        }.steps
        steps[0] shouldBe MissionStep.Land(porto, null, PrecisionLand.DISABLED)
        steps[1] shouldBe MissionStep.Land(Location(41.0, -8.0), 90.deg, PrecisionLand.REQUIRED)
        steps[2] shouldBe MissionStep.Waypoint(Location(41.0, -8.0, 10.m))
    }

    "returnHome returns by the autopilot's procedure and leaves the vehicle on the ground at home" {
        val mission = fromPorto { takeOff(30.m); move(north = 300.m); returnHome(); move(up = 5.m) }
        mission.steps[2] shouldBe MissionStep.ReturnHome
        mission.steps[3] shouldBe MissionStep.Waypoint(porto.copy(altitude = 5.m))
    }

    "returnHome without a home leaves the position unknown" {
        shouldThrow<IllegalArgumentException> { mission { goPos(porto); returnHome(); move(up = 5.m) } }
            .message shouldBe "move: no current position; call home(…) or goPos(…) first"
    }

    "returnHomeAndLoiter circles home at the current height until the mission ends" {
        val mission = fromPorto { takeOff(30.m); move(north = 300.m, up = 20.m); returnHomeAndLoiter() }
        mission.steps.last() shouldBe MissionStep.Loiter(porto.copy(altitude = 50.m), 15.m, LoiterDuration.Unlimited)
        mission.completion shouldBe MissionCompletion.LOITERING
    }

    "returnHomeAndLand flies over home at the current height and lands there" {
        val mission = fromPorto { takeOff(30.m); move(north = 300.m); returnHomeAndLand() }
        mission.steps.takeLast(2) shouldBe listOf(MissionStep.Waypoint(porto.copy(altitude = 30.m)), MissionStep.Land(porto))
        mission.completion shouldBe MissionCompletion.LANDED
    }

    "speed sets each given speed in order air, ground, climb, descent" {
        mission { speed(ground = 8.mps, air = 15.mps, descent = 2.mps) }.steps shouldBe listOf(
            MissionStep.ChangeSpeed(SpeedKind.AIR, 15.mps),
            MissionStep.ChangeSpeed(SpeedKind.GROUND, 8.mps),
            MissionStep.ChangeSpeed(SpeedKind.DESCENT, 2.mps),
        )
        shouldThrow<IllegalArgumentException> { mission { speed() } }.message shouldBe "speed: give at least one of air, ground, climb, descent"
    }

    "altitude changes the height and the next move starts from it" {
        val steps = fromPorto { takeOff(30.m); altitude(100.m); move(north = 10.m) }.steps
        steps[1] shouldBe MissionStep.ChangeAltitude(100.m)
        steps[2].shouldBeInstanceOf<MissionStep.Waypoint>().location.altitude shouldBe 100.m
    }

    "delay and the capture commands add their action steps" {
        mission {
            delay(10.seconds)
            capturePhoto()
            captureSeveralPhotos(5)
            captureSeveralPhotos(3, interval = 1.seconds)
            captureUntilStop()
            stopCapturing()
        }.steps shouldBe listOf(
            MissionStep.Delay(10.seconds),
            MissionStep.StartCapture(1, Duration.ZERO),
            MissionStep.StartCapture(5, 2.seconds),
            MissionStep.StartCapture(3, 1.seconds),
            MissionStep.StartCapture(0, 2.seconds),
            MissionStep.StopCapture,
        )
    }

    "surveyArea flies the planned lawn-mower from the current position and ends on the far edge" {
        val steps = fromPorto { takeOff(40.m); surveyArea(length = 300.m, width = 200.m) }.steps.drop(1)
        steps shouldHaveSize 10
        val points = steps.map { it.shouldBeInstanceOf<MissionStep.Waypoint>().location }
        points.first().shouldBeNear(porto.copy(altitude = 40.m))
        points.last().shouldBeNear(porto.offset(300.m, 200.m, 40.m))
    }

    "surveyArea from a given location flies at that location's height, and the next move starts at its end" {
        val corner = Location(41.0, -8.0, 70.m)
        val steps = fromPorto { surveyArea(100.m, 100.m, spacing = 100.m, direction = SurveyDirection.SOUTH_WEST, from = corner); move(up = 5.m) }.steps
        steps.first() shouldBe MissionStep.Waypoint(corner)
        steps.last().shouldBeInstanceOf<MissionStep.Waypoint>().location.shouldBeNear(corner.offset(0.m, (-100).m, 5.m))
    }

    "a survey with more than 1000 tracks is refused" {
        shouldThrow<IllegalArgumentException> { fromPorto { surveyArea(1_000.m, 20_000.m, spacing = 10.m) } }
            .message shouldContain "surveyArea: width / spacing must give at most 1000 tracks, was 2001"
    }

    "a mission with no steps fails when it is built" {
        shouldThrow<IllegalArgumentException> { mission("empty") { home(porto) } }.message shouldContain "mission \"empty\": no steps"
    }

    "relative commands without a position and FromHome commands without a home say what to call first" {
        shouldThrow<IllegalArgumentException> { mission { move(north = 10.m) } }
            .message shouldBe "move: no current position; call home(…) or goPos(…) first"
        shouldThrow<IllegalArgumentException> { mission { takeOff(10.m) } }
            .message shouldBe "takeOff: no current position; call home(…) or goPos(…) first"
        shouldThrow<IllegalArgumentException> { mission { goPos(porto); moveAndLoiterTurnsFromHome(up = 10.m, turns = 1) } }
            .message shouldBe "moveAndLoiterTurnsFromHome: no home; call home(…) first"
        shouldThrow<IllegalArgumentException> { mission { goPos(porto); returnHomeAndLand() } }
            .message shouldBe "returnHomeAndLand: no home; call home(…) first"
    }

    "bad arguments are refused at the call with the argument, its value and the allowed range" {
        shouldThrow<IllegalArgumentException> { fromPorto { loiterTurns(porto, turns = -1) } }
            .message shouldBe "loiterTurns: turns must be in 1..1000, was -1"
        shouldThrow<IllegalArgumentException> { fromPorto { takeOff((-5).m) } }
            .message shouldBe "takeOff: height must be in 1.0 m..10000.0 m, was -5.0 m"
        shouldThrow<IllegalArgumentException> { fromPorto { speed(air = 0.mps) } }
            .message shouldBe "speed: air must be greater than 0.0 m/s and at most 100.0 m/s, was 0.0 m/s"
        shouldThrow<IllegalArgumentException> { fromPorto { takeOff(20.m); move(up = (-30).m) } }
            .message shouldBe "move: up = -30.0 m from height 20.0 m gives a height of -10.0 m, which must be in 0.0 m..10000.0 m"
        shouldThrow<IllegalArgumentException> { mission { goPos(91.0, 0.0, 10.m) } }
            .message shouldBe "goPos: latitude must be in -90.0..90.0, was 91.0"
    }
})
