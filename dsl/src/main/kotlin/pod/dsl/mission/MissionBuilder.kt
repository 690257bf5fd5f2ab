package pod.dsl

import pod.core.mission.LoiterDuration
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.mission.PrecisionLand
import pod.core.mission.SurveyDirection
import pod.core.mission.SurveyPlanner
import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import kotlin.time.Duration

/**
 * Builds a [Mission] with the commands of Dolphin's MAVLink plugin:
 *
 * ```
 * val survey = mission("survey") {
 *     home(41.178, -8.596)
 *     takeOff(30.m)
 *     move(north = 100.m, up = 20.m)
 *     surveyArea(length = 300.m, width = 200.m, spacing = 40.m)
 *     returnHomeAndLand()
 * }
 * ```
 *
 * Every argument is checked when the command is called, and a bad one fails with an
 * [IllegalArgumentException] naming the command, the argument, its value and the allowed range.
 * Heights are above home. Every command that moves the vehicle updates [position], the point that
 * the next relative command (`move`, `moveAndLoiter…`, `surveyArea`, `returnHome…`) starts from.
 *
 * docs/dsl-missions.md lists each command, the step it makes, its defaults and its limits.
 */
@PodDsl
public class MissionBuilder internal constructor(private var name: String) {
    private var home: Location? = null
    private val steps = mutableListOf<MissionStep>()

    /** Where the vehicle is after the commands so far (height above home), or null when unknown. */
    public var position: Location? = null
        private set

    /** Names the mission (for people and logs). */
    public fun name(name: String) {
        require(name.isNotBlank()) { "name: name must not be blank, was \"$name\"" }
        this.name = name
    }

    /**
     * Sets the launch point: heights are measured from the ground there, and the vehicle starts
     * there on the ground. The [location]'s own altitude is kept as given in [Mission.home].
     */
    public fun home(location: Location) {
        requireIn("home", "location altitude", location.altitude, MissionLimits.homeAltitude)
        home = location
        position = location.copy(altitude = Distance.ZERO)
    }

    /** Sets the launch point at [latitude], [longitude], keeping [altitude] as its own altitude (see the other overload). */
    public fun home(latitude: Double, longitude: Double, altitude: Distance = Distance.ZERO) {
        requireIn("home", "altitude", altitude, MissionLimits.homeAltitude)
        home(coordinates("home", latitude, longitude, altitude, checkHeight = false))
    }

    /** Flies to [location] (a [MissionStep.Waypoint]). */
    public fun goPos(location: Location) {
        waypoint(checked("goPos", location))
    }

    /** Flies to [latitude], [longitude] at [height] above home. */
    public fun goPos(latitude: Double, longitude: Double, height: Distance) {
        waypoint(coordinates("goPos", latitude, longitude, height))
    }

    /**
     * Takes off where the vehicle is (normally home) and climbs to [height]; planes climb at
     * [pitch]. The next relative command starts from that height.
     */
    public fun takeOff(height: Distance, pitch: Angle = 15.deg) {
        requireIn("takeOff", "height", height, MissionLimits.takeOffHeight)
        requireIn("takeOff", "pitch", pitch, MissionLimits.pitch)
        val ground = current("takeOff")
        add(MissionStep.TakeOff(ground.copy(altitude = height), pitch))
    }

    /** Flies [north], [east] and [up] from the current position (negative values go south, west, down). */
    public fun move(north: Distance = 0.m, east: Distance = 0.m, up: Distance = 0.m) {
        waypoint(fromHere("move", north, east, up))
    }

    /** Flies to the point [north] and [east] of home at [up] above it. */
    public fun moveFromHome(north: Distance = 0.m, east: Distance = 0.m, up: Distance = 0.m) {
        waypoint(fromHome("moveFromHome", north, east, up))
    }

    /** Flies [north], [east] and [up] from the current position and circles there until the mission ends. */
    public fun moveAndLoiterPos(north: Distance = 0.m, east: Distance = 0.m, up: Distance = 0.m, radius: Distance = 15.m) {
        loiter("moveAndLoiterPos", fromHere("moveAndLoiterPos", north, east, up), radius, LoiterDuration.Unlimited)
    }

    /** Flies [north], [east] and [up] from the current position and circles there [turns] times. */
    public fun moveAndLoiterTurns(north: Distance = 0.m, east: Distance = 0.m, up: Distance = 0.m, turns: Int, radius: Distance = 15.m) {
        loiter("moveAndLoiterTurns", fromHere("moveAndLoiterTurns", north, east, up), radius, turns("moveAndLoiterTurns", turns))
    }

    /** Flies [north], [east] and [up] from the current position and circles there for [time]. */
    public fun moveAndLoiterTime(north: Distance = 0.m, east: Distance = 0.m, up: Distance = 0.m, time: Duration, radius: Distance = 15.m) {
        loiter("moveAndLoiterTime", fromHere("moveAndLoiterTime", north, east, up), radius, time("moveAndLoiterTime", time))
    }

    /** Flies to [north], [east] of home at [up] above it and circles there until the mission ends. */
    public fun moveAndLoiterPosFromHome(north: Distance = 0.m, east: Distance = 0.m, up: Distance = 0.m, radius: Distance = 15.m) {
        val command = "moveAndLoiterPosFromHome"
        loiter(command, fromHome(command, north, east, up), radius, LoiterDuration.Unlimited)
    }

    /** Flies to [north], [east] of home at [up] above it and circles there [turns] times. */
    public fun moveAndLoiterTurnsFromHome(north: Distance = 0.m, east: Distance = 0.m, up: Distance = 0.m, turns: Int, radius: Distance = 15.m) {
        val command = "moveAndLoiterTurnsFromHome"
        loiter(command, fromHome(command, north, east, up), radius, turns(command, turns))
    }

    /** Flies to [north], [east] of home at [up] above it and circles there for [time]. */
    public fun moveAndLoiterTimeFromHome(north: Distance = 0.m, east: Distance = 0.m, up: Distance = 0.m, time: Duration, radius: Distance = 15.m) {
        val command = "moveAndLoiterTimeFromHome"
        loiter(command, fromHome(command, north, east, up), radius, time(command, time))
    }

    /** Flies to [location] and circles it at [radius] until the mission ends. */
    public fun loiterPos(location: Location, radius: Distance = 15.m) {
        loiter("loiterPos", checked("loiterPos", location), radius, LoiterDuration.Unlimited)
    }

    /** Flies to [latitude], [longitude] at [height] above home and circles there until the mission ends. */
    public fun loiterPos(latitude: Double, longitude: Double, height: Distance, radius: Distance = 15.m) {
        loiter("loiterPos", coordinates("loiterPos", latitude, longitude, height), radius, LoiterDuration.Unlimited)
    }

    /** Flies to [location] and circles it [turns] times at [radius]. */
    public fun loiterTurns(location: Location, turns: Int, radius: Distance = 15.m) {
        loiter("loiterTurns", checked("loiterTurns", location), radius, turns("loiterTurns", turns))
    }

    /** Flies to [latitude], [longitude] at [height] above home and circles there [turns] times. */
    public fun loiterTurns(latitude: Double, longitude: Double, height: Distance, turns: Int, radius: Distance = 15.m) {
        val at = coordinates("loiterTurns", latitude, longitude, height)
        loiter("loiterTurns", at, radius, turns("loiterTurns", turns))
    }

    /** Flies to [location] and circles it at [radius] for [time]. */
    public fun loiterTime(location: Location, time: Duration, radius: Distance = 15.m) {
        loiter("loiterTime", checked("loiterTime", location), radius, time("loiterTime", time))
    }

    /** Flies to [latitude], [longitude] at [height] above home and circles there for [time]. */
    public fun loiterTime(latitude: Double, longitude: Double, height: Distance, time: Duration, radius: Distance = 15.m) {
        val at = coordinates("loiterTime", latitude, longitude, height)
        loiter("loiterTime", at, radius, time("loiterTime", time))
    }

    /**
     * Lands at [location] (its height is ignored), facing [yaw] (null keeps the heading), on a
     * precision target if [precisionLand] asks for one. The vehicle is then on the ground there.
     */
    public fun landingPoint(location: Location, yaw: Angle? = null, precisionLand: PrecisionLand = PrecisionLand.DISABLED) {
        if (yaw != null) requireIn("landingPoint", "yaw", yaw, MissionLimits.yaw)
        val ground = location.copy(altitude = Distance.ZERO)
        add(MissionStep.Land(ground, yaw, precisionLand))
    }

    /** Lands at [latitude], [longitude]; see the other overload. */
    public fun landingPoint(latitude: Double, longitude: Double, yaw: Angle? = null, precisionLand: PrecisionLand = PrecisionLand.DISABLED) {
        landingPoint(coordinates("landingPoint", latitude, longitude, Distance.ZERO), yaw, precisionLand)
    }

    /**
     * Returns to launch by the autopilot's own procedure (multirotors land there). Afterwards the
     * vehicle counts as on the ground at home, or at an unknown position when no home was set.
     */
    public fun returnHome() {
        steps += MissionStep.ReturnHome
        position = home?.copy(altitude = Distance.ZERO)
    }

    /** Flies back over home at the current height and circles there until the mission ends. */
    public fun returnHomeAndLoiter(radius: Distance = 15.m) {
        val command = "returnHomeAndLoiter"
        loiter(command, homeGround(command).copy(altitude = current(command).altitude), radius, LoiterDuration.Unlimited)
    }

    /** Flies back over home at the current height, then lands there. */
    public fun returnHomeAndLand() {
        val command = "returnHomeAndLand"
        val ground = homeGround(command)
        waypoint(ground.copy(altitude = current(command).altitude))
        add(MissionStep.Land(ground))
    }

    /** Climbs or descends to [height] above home where the vehicle is, then goes on. */
    public fun altitude(height: Distance) {
        requireIn("altitude", "height", height, MissionLimits.height)
        steps += MissionStep.ChangeAltitude(height)
        position = position?.copy(altitude = height)
    }

    /**
     * Flies a lawn-mower survey of a [length] × [width] rectangle (length north–south, width
     * east–west) that extends toward [direction] from [from] (default: the current position), with
     * tracks at most [spacing] apart, at [from]'s height. See [SurveyPlanner] for the geometry.
     */
    public fun surveyArea(
        length: Distance,
        width: Distance,
        spacing: Distance = 50.m,
        direction: SurveyDirection = SurveyDirection.NORTH_EAST,
        from: Location? = null,
    ) {
        val command = "surveyArea"
        requirePositive(command, "length", length, Distance.ZERO, MissionLimits.areaSide)
        requirePositive(command, "width", width, Distance.ZERO, MissionLimits.areaSide)
        requireIn(command, "spacing", spacing, MissionLimits.spacing)
        val start = if (from == null) current(command) else checked(command, from, "from")
        val tracks = SurveyPlanner.trackCount(width, spacing)
        require(tracks <= MissionLimits.SURVEY_TRACKS) {
            "$command: width / spacing must give at most ${MissionLimits.SURVEY_TRACKS} tracks, was $tracks ($width / $spacing)"
        }
        val points = try {
            SurveyPlanner.lawnMower(start, length, width, spacing, direction, start.altitude)
        } catch (e: IllegalArgumentException) {
            throw IllegalArgumentException("$command: the area leaves the map from $start: ${e.message}", e)
        }
        points.forEach(::waypoint)
    }

    internal fun add(step: MissionStep) {
        steps += step
        if (step is MissionStep.Navigation) position = step.location
    }

    internal fun build(): Mission {
        require(steps.isNotEmpty()) { "mission \"$name\": no steps; add at least one command, such as goPos(…) or takeOff(…)" }
        return Mission(name, home, steps.toList())
    }

    private fun waypoint(location: Location) = add(MissionStep.Waypoint(location))

    private fun loiter(command: String, at: Location, radius: Distance, duration: LoiterDuration) {
        requireIn(command, "radius", radius, MissionLimits.radius)
        add(MissionStep.Loiter(at, radius, duration))
    }

    private fun current(command: String): Location =
        requireNotNull(position) { "$command: no current position; call home(…) or goPos(…) first" }

    private fun fromHere(command: String, north: Distance, east: Distance, up: Distance): Location =
        relative(command, current(command), north, east, up)

    private fun fromHome(command: String, north: Distance, east: Distance, up: Distance): Location =
        relative(command, homeGround(command), north, east, up)

    private fun homeGround(command: String): Location =
        requireNotNull(home) { "$command: no home; call home(…) first" }.copy(altitude = Distance.ZERO)

    private fun relative(command: String, origin: Location, north: Distance, east: Distance, up: Distance): Location {
        requireIn(command, "north", north, MissionLimits.offset)
        requireIn(command, "east", east, MissionLimits.offset)
        requireIn(command, "up", up, MissionLimits.offset)
        val target = try {
            origin.offset(north, east, up)
        } catch (e: IllegalArgumentException) {
            throw IllegalArgumentException("$command: north = $north, east = $east from $origin leaves the map: ${e.message}", e)
        }
        require(target.altitude in MissionLimits.height) {
            "$command: up = $up from height ${origin.altitude} gives a height of ${target.altitude}, " +
                "which must be in ${MissionLimits.height.start}..${MissionLimits.height.endInclusive}"
        }
        return target
    }

    private fun checked(command: String, location: Location, argument: String = "location"): Location {
        requireIn(command, "$argument height", location.altitude, MissionLimits.height)
        return location
    }

    private fun coordinates(command: String, latitude: Double, longitude: Double, height: Distance, checkHeight: Boolean = true): Location {
        requireIn(command, "latitude", latitude, MissionLimits.latitude)
        requireIn(command, "longitude", longitude, MissionLimits.longitude)
        if (checkHeight) requireIn(command, "height", height, MissionLimits.height)
        return Location(latitude, longitude, height)
    }

    private fun turns(command: String, turns: Int): LoiterDuration {
        requireIn(command, "turns", turns, MissionLimits.turns)
        return LoiterDuration.Turns(turns)
    }

    private fun time(command: String, time: Duration): LoiterDuration {
        requirePositive(command, "time", time, Duration.ZERO, MissionLimits.loiterTime)
        return LoiterDuration.Time(time)
    }
}
