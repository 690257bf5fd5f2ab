package pod.mavlink.plan

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.string.shouldContain
import pod.core.mission.LoiterDuration
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.mavlink.command.MavCommands
import pod.mavlink.executor.MissionNotFlyable

/**
 * No waypoint or loiter leaves the planner at 0 m: a step planned "at the current height" from the
 * ground at home takes the height flown before it, or the vehicle's own at upload.
 */
class SafeHeightPlanTest : StringSpec({
    val home = Location(41.178, -8.596, 120.m)
    val ground = home.copy(altitude = 0.m)
    val over = home.offset(north = 55.m, east = 0.m).copy(altitude = 0.m)
    val returnAndLand = listOf(MissionStep.Waypoint(ground), MissionStep.Land(ground))

    /** Heights (z) of the NAV_WAYPOINT and loiter items of [steps] planned for every flavour. */
    fun heights(steps: List<MissionStep>, heightNow: Double?, flavor: MissionFlavor): List<Float> =
        MissionPlanner.plan(Mission("m", home, steps), flavor, home, heightNow?.m).items
            .drop(flavor.firstItem)
            .filter { it.command == MavCommands.NAV_WAYPOINT || it.command == MavCommands.NAV_LOITER_UNLIM }
            .map { it.z }

    for (flavor in MissionFlavor.entries) {
        "$flavor: the way home from the air is sent at the vehicle's height, never at 0 m" {
            heights(returnAndLand, 30.0, flavor).filter { it < 1f } shouldContainExactly emptyList()
            heights(returnAndLand, 30.0, flavor).first() shouldContainExactlyHeight 30f
        }

        "$flavor: a step at the current height after a take-off flies at the take-off's height" {
            val steps = listOf(MissionStep.TakeOff(ground.copy(altitude = 25.m), 15.deg), MissionStep.Waypoint(over), MissionStep.Loiter(over, 20.m, LoiterDuration.Unlimited))
            heights(steps, null, flavor).takeLast(2) shouldContainExactly listOf(25f, 25f)
        }

        "$flavor: a step at the current height with nothing flying before it is refused, naming the step" {
            val failure = shouldThrow<MissionNotFlyable> { heights(returnAndLand, null, flavor) }
            failure.message!! shouldContain "step 1 (a waypoint) is 0.0 m above home"
            // A vehicle hovering just off the ground is not flying at a height either.
            shouldThrow<MissionNotFlyable> { heights(returnAndLand, 0.4, flavor) }
        }
    }
})

private infix fun Float.shouldContainExactlyHeight(expected: Float) = listOf(this) shouldContainExactly listOf(expected)
