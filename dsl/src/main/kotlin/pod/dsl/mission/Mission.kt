package pod.dsl

import pod.core.mission.Mission

/**
 * Builds a [Mission] named [name] from the commands in [build]; fails with an
 * [IllegalArgumentException] on the first bad argument, or when [build] adds no step.
 *
 * ```
 * val patrol = mission("patrol") {
 *     home(41.178, -8.596)
 *     takeOff(30.m)
 *     moveAndLoiterTurns(north = 200.m, turns = 3)
 *     returnHomeAndLand()
 * }
 * ```
 *
 * @see MissionBuilder for every command.
 */
public fun mission(name: String = "mission", build: MissionBuilder.() -> Unit): Mission {
    require(name.isNotBlank()) { "mission: name must not be blank, was \"$name\"" }
    return MissionBuilder(name).apply(build).build()
}
