package pod.dsl

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.property.Arb
import io.kotest.property.arbitrary.bind
import io.kotest.property.arbitrary.choice
import io.kotest.property.arbitrary.constant
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.checkAll
import pod.core.mission.MissionCompletion
import pod.core.mission.MissionStep
import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.units.mps
import kotlin.math.abs
import kotlin.math.hypot
import kotlin.math.nextDown
import kotlin.math.nextUp
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** One way to call a builder command with an argument outside its range. */
private class BadArgument<T>(val command: String, val argument: String, val values: Arb<T>, val call: MissionBuilder.(T) -> Unit)

/** Doubles below [min] (or at it, when [min] itself is refused) or above [max], and NaN. */
private fun outside(min: Double, max: Double, minAllowed: Boolean = true): Arb<Double> = Arb.choice(
    Arb.double(-1e7, if (minAllowed) min.nextDown() else min, includeNaNs = false),
    Arb.double(max.nextUp(), 1e7, includeNaNs = false),
    Arb.constant(Double.NaN),
)

private fun distancesOutside(min: Double, max: Double, minAllowed: Boolean = true): Arb<Distance> =
    outside(min, max, minAllowed).map { it.m }

private fun anglesOutside(min: Double, max: Double): Arb<Angle> = outside(min, max).map { it.deg }

private fun intsOutside(range: IntRange): Arb<Int> =
    Arb.choice(Arb.int(Int.MIN_VALUE, range.first - 1), Arb.int(range.last + 1, Int.MAX_VALUE))

/** Durations of zero or less, or above [max]. */
private fun durationsOutside(max: Duration, zeroAllowed: Boolean): Arb<Duration> = Arb.choice(
    Arb.long(-1_000_000_000L, if (zeroAllowed) -1L else 0L).map { it.milliseconds },
    Arb.long(max.inWholeMilliseconds + 1, max.inWholeMilliseconds * 1000).map { it.milliseconds },
)

private val badArguments: List<BadArgument<*>> = listOf(
    BadArgument("home", "latitude", outside(-90.0, 90.0)) { home(it, 0.0) },
    BadArgument("home", "longitude", outside(-180.0, 180.0)) { home(0.0, it) },
    BadArgument("home", "altitude", distancesOutside(-1000.0, 10_000.0)) { home(0.0, 0.0, it) },
    BadArgument("goPos", "latitude", outside(-90.0, 90.0)) { goPos(it, 0.0, 10.m) },
    BadArgument("goPos", "longitude", outside(-180.0, 180.0)) { goPos(0.0, it, 10.m) },
    BadArgument("goPos", "height", distancesOutside(0.0, 10_000.0)) { goPos(0.0, 0.0, it) },
    BadArgument("goPos", "location height", distancesOutside(0.0, 10_000.0)) { goPos(porto.copy(altitude = it)) },
    BadArgument("takeOff", "height", distancesOutside(1.0, 10_000.0)) { takeOff(it) },
    BadArgument("takeOff", "pitch", anglesOutside(0.0, 90.0)) { takeOff(10.m, pitch = it) },
    BadArgument("move", "north", distancesOutside(-50_000.0, 50_000.0)) { move(north = it) },
    BadArgument("move", "east", distancesOutside(-50_000.0, 50_000.0)) { move(east = it) },
    BadArgument("move", "up", distancesOutside(-50.0, 9_950.0)) { move(up = it) },
    BadArgument("moveFromHome", "up", distancesOutside(0.0, 10_000.0)) { moveFromHome(up = it) },
    BadArgument("moveAndLoiterTurns", "turns", intsOutside(1..1000)) { moveAndLoiterTurns(turns = it) },
    BadArgument("moveAndLoiterTime", "time", durationsOutside(24.hours, zeroAllowed = false)) { moveAndLoiterTime(time = it) },
    BadArgument("moveAndLoiterPosFromHome", "radius", distancesOutside(1.0, 10_000.0)) { moveAndLoiterPosFromHome(up = 9.m, radius = it) },
    BadArgument("loiterTurns", "turns", intsOutside(1..1000)) { loiterTurns(porto, turns = it) },
    BadArgument("loiterTime", "time", durationsOutside(24.hours, zeroAllowed = false)) { loiterTime(porto, time = it) },
    BadArgument("loiterPos", "radius", distancesOutside(1.0, 10_000.0)) { loiterPos(porto, radius = it) },
    BadArgument("landingPoint", "yaw", anglesOutside(0.0, 360.0)) { landingPoint(porto, yaw = it) },
    BadArgument("returnHomeAndLoiter", "radius", distancesOutside(1.0, 10_000.0)) { returnHomeAndLoiter(radius = it) },
    BadArgument("speed", "air", outside(0.0, 100.0, minAllowed = false).map { it.mps }) { speed(air = it) },
    BadArgument("speed", "ground", outside(0.0, 100.0, minAllowed = false).map { it.mps }) { speed(ground = it) },
    BadArgument("speed", "climb", outside(0.0, 100.0, minAllowed = false).map { it.mps }) { speed(climb = it) },
    BadArgument("speed", "descent", outside(0.0, 100.0, minAllowed = false).map { it.mps }) { speed(descent = it) },
    BadArgument("altitude", "height", distancesOutside(0.0, 10_000.0)) { altitude(it) },
    BadArgument("delay", "duration", durationsOutside(24.hours, zeroAllowed = true)) { delay(it) },
    BadArgument("surveyArea", "length", distancesOutside(0.0, 50_000.0, minAllowed = false)) { surveyArea(it, 100.m) },
    BadArgument("surveyArea", "width", distancesOutside(0.0, 50_000.0, minAllowed = false)) { surveyArea(100.m, it) },
    BadArgument("surveyArea", "spacing", distancesOutside(1.0, 10_000.0)) { surveyArea(100.m, 100.m, spacing = it) },
    BadArgument("captureSeveralPhotos", "count", intsOutside(1..10_000)) { captureSeveralPhotos(it) },
    BadArgument("captureSeveralPhotos", "interval", durationsOutside(1.hours, zeroAllowed = false)) { captureSeveralPhotos(3, it) },
    BadArgument("captureUntilStop", "interval", durationsOutside(1.hours, zeroAllowed = false)) { captureUntilStop(it) },
)

/** A builder command that the completion property picks at random, and how it changes completion (null: it does not). */
private class Command(val name: String, val completion: MissionCompletion?, val call: MissionBuilder.() -> Unit)

private val commands = listOf(
    Command("goPos", MissionCompletion.LAST_STEP_DONE) { goPos(porto.copy(altitude = 30.m)) },
    Command("move", MissionCompletion.LAST_STEP_DONE) { move(north = 50.m, up = 20.m) },
    Command("moveFromHome", MissionCompletion.LAST_STEP_DONE) { moveFromHome(east = 50.m, up = 20.m) },
    Command("takeOff", MissionCompletion.LAST_STEP_DONE) { takeOff(25.m) },
    Command("surveyArea", MissionCompletion.LAST_STEP_DONE) { surveyArea(100.m, 100.m) },
    Command("loiterTurns", MissionCompletion.LAST_STEP_DONE) { moveAndLoiterTurns(north = 10.m, up = 10.m, turns = 2) },
    Command("loiterTime", MissionCompletion.LAST_STEP_DONE) { loiterTime(porto.copy(altitude = 40.m), 30.seconds) },
    Command("loiterPos", MissionCompletion.LOITERING) { moveAndLoiterPos(up = 30.m) },
    Command("returnHomeAndLoiter", MissionCompletion.LOITERING) { returnHomeAndLoiter() },
    Command("landingPoint", MissionCompletion.LANDED) { landingPoint(porto.offset(20.m, 0.m)) },
    Command("returnHome", MissionCompletion.LANDED) { returnHome() },
    Command("returnHomeAndLand", MissionCompletion.LANDED) { returnHomeAndLand() },
    Command("speed", null) { speed(ground = 5.mps) },
    Command("altitude", null) { altitude(60.m) },
    Command("delay", null) { delay(5.seconds) },
    Command("capturePhoto", null) { capturePhoto() },
    Command("captureUntilStop", null) { captureUntilStop() },
    Command("stopCapturing", null) { stopCapturing() },
)

class MissionBuilderPropertyTest : StringSpec({

    "after any sequence of relative moves the position is the start offset by the sum of the moves" {
        val moves = Arb.list(
            Arb.bind(
                Arb.double(-200.0, 200.0, includeNaNs = false),
                Arb.double(-200.0, 200.0, includeNaNs = false),
                Arb.double(-20.0, 20.0, includeNaNs = false),
            ) { north, east, up -> Triple(north, east, up) },
            1..20,
        )
        checkAll(
            Arb.double(-60.0, 60.0, includeNaNs = false),
            Arb.double(-170.0, 170.0, includeNaNs = false),
            moves,
        ) { lat, lon, offsets ->
            val start = Location(lat, lon, 500.m)
            var end: Location? = null
            mission {
                goPos(start)
                offsets.forEach { (north, east, up) -> move(north.m, east.m, up.m) }
                end = position
            }
            val expected = start.offset(offsets.sumOf { it.first }.m, offsets.sumOf { it.second }.m, offsets.sumOf { it.third }.m)
            // Each move scales east by the cosine of its own latitude: allow 0.1 % of the path flown.
            val path = offsets.sumOf { hypot(it.first, it.second) }
            end!!.shouldBeNear(expected, tolerance = 0.01 + path * 1e-3)
        }
    }

    "takeOff then move(up = x) ends at the takeoff height plus x" {
        checkAll(
            Arb.double(1.0, 5_000.0, includeNaNs = false),
            Arb.double(-1.0, 5_000.0, includeNaNs = false),
        ) { height, fraction ->
            val up = if (fraction < 0) -height * abs(fraction) else fraction
            val mission = fromPorto {
                takeOff(height.m)
                move(north = 10.m, up = up.m)
            }
            val end = mission.steps.last().shouldBeInstanceOf<MissionStep.Waypoint>().location
            end.altitude.meters shouldBe ((height + up) plusOrMinus 1e-9)
        }
    }

    "an out-of-range argument always throws, naming the command and the argument" {
        for (bad in badArguments) {
            @Suppress("UNCHECKED_CAST")
            val case = bad as BadArgument<Any?>
            checkAll(200, case.values) { value ->
                withClue("${case.command}(${case.argument} = $value)") {
                    val error = shouldThrow<IllegalArgumentException> {
                        fromPorto {
                            takeOff(50.m)
                            case.call(this, value)
                        }
                    }
                    error.message shouldContain "${case.command}: ${case.argument}"
                }
            }
        }
    }

    "Mission.completion follows the last command that moves the vehicle" {
        checkAll(Arb.list(Arb.element(commands), 0..12)) { sequence ->
            val mission = fromPorto {
                takeOff(20.m)
                sequence.forEach { it.call(this) }
            }
            val expected = sequence.mapNotNull { it.completion }.lastOrNull() ?: MissionCompletion.LAST_STEP_DONE
            withClue(sequence.map { it.name }) { mission.completion shouldBe expected }
        }
    }
})
