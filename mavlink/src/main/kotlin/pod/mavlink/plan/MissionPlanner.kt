package pod.mavlink.plan

import kotlin.math.PI
import kotlin.math.abs
import kotlin.math.roundToLong
import kotlin.time.DurationUnit
import pod.core.mission.LoiterDuration
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.mission.PrecisionLand
import pod.core.mission.SpeedKind
import pod.mavlink.command.SpeedTypes
import pod.mavlink.MavFrames
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.vehicle.CLEAR_OF_GROUND
import pod.mavlink.command.MavCommands
import pod.mavlink.executor.MissionNotFlyable
import pod.mavlink.command.VehicleCommand
import pod.mavlink.mission.MissionItem

/**
 * Turns a protocol-neutral [Mission] into the [MissionPlan] one autopilot flavour flies.
 *
 * Items travel as MISSION_ITEM_INT in MAV_FRAME_GLOBAL_RELATIVE_ALT (heights above home); items
 * without a position in MAV_FRAME_MISSION, which PX4 requires for them. What differs per flavour,
 * from ArduPilot's and PX4's mission parsers:
 * - ArduPilot: item 0 is home (absolute altitude).
 * - Fixed-wing: a landing is preceded by an approach waypoint ([LandingApproach]) from which the
 *   glide is a few degrees; no DO_LAND_START (ArduPlane would refuse to arm with its defaults).
 * - ArduCopter and PX4 have no NAV_CONTINUE_AND_CHANGE_ALT: a change of altitude becomes a
 *   waypoint over the previous position at the new height. ArduPlane flies it as that item.
 * - PX4 refuses NAV_LOITER_TURNS: the turns become NAV_LOITER_TIME for as long as the circles take
 *   at [LOITER_TURN_SPEED_MPS] (at least [MIN_SECONDS_PER_TURN] per turn).
 * - ArduPlane and PX4 take only air and ground speed in a mission's DO_CHANGE_SPEED: a climb or
 *   descent rate is sent as a command when the vehicle reaches the next item.
 * - The vehicle keeps its own home: heights are relative to it, and a mission's `home` is only where
 *   its relative moves were planned from (its altitude may be unknown), so no DO_SET_HOME is sent.
 * - No waypoint or loiter is ever sent at 0 m. A step lower than [CLEAR_OF_GROUND] above home (the
 *   builder's "at the current height" for a mission planned from the ground at home, such as
 *   `home(h); returnHomeAndLand()`) is sent at the height the vehicle flies at before it: the
 *   previous step's, or the vehicle's own at upload. The autopilots disagree on a zero altitude
 *   (ArduCopter flies it at its current altitude, ArduPlane only without a position, PX4 at ground
 *   level: see the simulator's ItemAltitude), so Pod never leaves it to them.
 */
public object MissionPlanner {
    /** MAV_FRAME_GLOBAL (altitude above mean sea level). */
    public const val FRAME_GLOBAL: Int = MavFrames.GLOBAL

    /** MAV_FRAME_GLOBAL_RELATIVE_ALT (altitude above home). */
    public const val FRAME_RELATIVE: Int = MavFrames.GLOBAL_RELATIVE_ALT

    /** Speed assumed to fly one turn of a loiter PX4 must fly as a timed loiter. */
    public const val LOITER_TURN_SPEED_MPS: Double = 5.0

    /** Shortest time per turn of a loiter PX4 must fly as a timed loiter. */
    public const val MIN_SECONDS_PER_TURN: Double = 10.0

    /**
     * The plan for [mission] on [flavor]; [home], the vehicle's own (altitude above sea level),
     * fills ArduPilot's item 0. [heightNow] is the vehicle's height above home when it is flying
     * (null on the ground): what a step "at the current height" before any other height means.
     * Throws IllegalArgumentException for an empty mission and [MissionNotFlyable] for a step
     * that would fly at ground level (it has no height and nothing before it flies).
     */
    public fun plan(mission: Mission, flavor: MissionFlavor, home: Location, heightNow: Distance? = null): MissionPlan {
        require(mission.steps.isNotEmpty()) { "mission \"${mission.name}\" has no steps" }
        val launch = home
        val out = Builder(flavor)
        if (flavor.homeAtZero) out.add(null, MissionItem(0, FRAME_GLOBAL, MavCommands.NAV_WAYPOINT, x = launch.latE7, y = launch.lonE7, z = launch.altitude.meters.toFloat()))
        var last = launch.copy(altitude = Distance.ZERO)
        var lastCourse: Double? = null
        // The height the vehicle flies at before the step being planned, or null on the ground.
        var flying: Distance? = heightNow?.takeIf { it >= CLEAR_OF_GROUND }
        mission.steps.forEachIndexed { index, original ->
            val step = withHeight(mission, index, original, flying)
            when (step) {
                is MissionStep.TakeOff -> out.add(index, positioned(MavCommands.NAV_TAKEOFF, step.location, p1 = if (flavor.fixedWing) step.pitch.degrees.toFloat() else 0f, p4 = yawUnchanged(flavor)))
                is MissionStep.Waypoint -> out.add(index, positioned(MavCommands.NAV_WAYPOINT, step.location, p1 = step.hold.toDouble(DurationUnit.SECONDS).toFloat(), p4 = yawUnchanged(flavor)))
                is MissionStep.Loiter -> out.add(index, loiter(step, flavor))
                is MissionStep.Land -> {
                    // No DO_LAND_START: ArduPlane refuses to arm a mission holding one while RTL_AUTOLAND is 0,
                    // its default (AP_Arming_Plane::mission_checks), and flies the landing in order without it.
                    if (flavor.fixedWing) {
                        val approach = LandingApproach.point(step.location, last, step.yaw, lastCourse)
                        out.add(index, positioned(MavCommands.NAV_WAYPOINT, approach, p4 = yawUnchanged(flavor)))
                    }
                    out.add(index, positioned(MavCommands.NAV_LAND, step.location.copy(altitude = Distance.ZERO), p2 = precision(step.precision).toFloat(), p4 = step.yaw?.degrees?.toFloat() ?: Float.NaN))
                }
                MissionStep.ReturnHome -> out.add(index, unpositioned(MavCommands.NAV_RETURN_TO_LAUNCH))
                is MissionStep.ChangeSpeed -> {
                    val rate = step.kind == SpeedKind.CLIMB || step.kind == SpeedKind.DESCENT
                    val p1 = SpeedTypes.of(step.kind).toFloat()
                    val p2 = step.speed.metersPerSecond.toFloat()
                    if (rate && !flavor.climbRateByItem) {
                        out.command(index, VehicleCommand(MavCommands.DO_CHANGE_SPEED, param1 = p1, param2 = p2, param3 = -1f))
                    } else {
                        out.add(index, unpositioned(MavCommands.DO_CHANGE_SPEED, p1 = p1, p2 = p2, p3 = -1f))
                    }
                }
                is MissionStep.ChangeAltitude -> if (flavor.changesAltitudeByItem) {
                    out.add(index, MissionItem(0, FRAME_RELATIVE, MavCommands.NAV_CONTINUE_AND_CHANGE_ALT, z = step.height.meters.toFloat()))
                } else {
                    out.add(index, positioned(MavCommands.NAV_WAYPOINT, last.copy(altitude = step.height), p4 = yawUnchanged(flavor)))
                }
                is MissionStep.Delay -> out.add(index, unpositioned(MavCommands.NAV_DELAY, p1 = step.duration.toDouble(DurationUnit.SECONDS).toFloat(), p2 = -1f, p3 = -1f, p4 = -1f))
                is MissionStep.StartCapture -> out.add(index, unpositioned(MavCommands.IMAGE_START_CAPTURE, p2 = step.interval.toDouble(DurationUnit.SECONDS).toFloat(), p3 = step.count.toFloat()))
                MissionStep.StopCapture -> out.add(index, unpositioned(MavCommands.IMAGE_STOP_CAPTURE))
            }
            val moved = (step as? MissionStep.Navigation)?.location ?: if (step == MissionStep.ReturnHome) launch else null
            if (moved != null) LandingApproach.bearing(last, moved)?.takeIf { last.distanceTo(moved).meters > 1.0 }?.let { lastCourse = it }
            when (step) {
                is MissionStep.Navigation -> last = step.location
                is MissionStep.ChangeAltitude -> last = last.copy(altitude = step.height)
                MissionStep.ReturnHome -> last = launch.copy(altitude = Distance.ZERO)
                else -> Unit
            }
            flying = when (step) {
                is MissionStep.Land, MissionStep.ReturnHome -> null
                is MissionStep.Navigation -> step.location.altitude
                is MissionStep.ChangeAltitude -> step.height
                else -> flying
            }?.takeIf { it >= CLEAR_OF_GROUND }
        }
        return out.build(mission.steps.size, emptyList())
    }

    /**
     * [step] with the height it is flown at: a waypoint or loiter lower than [CLEAR_OF_GROUND]
     * takes [flying], the height before it; without one, the mission cannot be flown as written.
     */
    private fun withHeight(mission: Mission, index: Int, step: MissionStep, flying: Distance?): MissionStep {
        val at = when (step) {
            is MissionStep.Waypoint -> step.location
            is MissionStep.Loiter -> step.location
            else -> return step
        }
        if (at.altitude >= CLEAR_OF_GROUND) return step
        val height = flying ?: throw MissionNotFlyable(
            mission.name,
            "step ${index + 1} (${if (step is MissionStep.Loiter) "a loiter" else "a waypoint"}) is ${at.altitude} above home, " +
                "and the vehicle does not fly before it: take off first or give the step a height",
        )
        return when (step) {
            is MissionStep.Waypoint -> step.copy(location = at.copy(altitude = height))
            is MissionStep.Loiter -> step.copy(location = at.copy(altitude = height))
            else -> step
        }
    }

    private fun loiter(step: MissionStep.Loiter, flavor: MissionFlavor): MissionItem {
        val radius = step.radius.meters.toFloat()
        return when (val d = step.duration) {
            LoiterDuration.Unlimited -> positioned(MavCommands.NAV_LOITER_UNLIM, step.location, p3 = radius, p4 = yawUnchanged(flavor))
            is LoiterDuration.Time -> positioned(MavCommands.NAV_LOITER_TIME, step.location, p1 = d.time.toDouble(DurationUnit.SECONDS).toFloat(), p3 = radius)
            is LoiterDuration.Turns -> if (!flavor.loitersByTurns) {
                val perTurn = maxOf(2 * PI * abs(step.radius.meters) / LOITER_TURN_SPEED_MPS, MIN_SECONDS_PER_TURN)
                positioned(MavCommands.NAV_LOITER_TIME, step.location, p1 = (perTurn * d.turns).toFloat(), p3 = radius)
            } else {
                positioned(MavCommands.NAV_LOITER_TURNS, step.location, p1 = d.turns.toFloat(), p3 = radius)
            }
        }
    }

    /** NaN (keep the heading) where PX4 reads param4 as a yaw; ArduPilot stores 0 there. */
    private fun yawUnchanged(flavor: MissionFlavor): Float = if (flavor.nanYawKeepsHeading) Float.NaN else 0f

    private fun positioned(command: Int, at: Location, p1: Float = 0f, p2: Float = 0f, p3: Float = 0f, p4: Float = 0f) =
        MissionItem(0, FRAME_RELATIVE, command, param1 = p1, param2 = p2, param3 = p3, param4 = p4, x = at.latE7, y = at.lonE7, z = at.altitude.meters.toFloat())

    private fun unpositioned(command: Int, p1: Float = 0f, p2: Float = 0f, p3: Float = 0f, p4: Float = 0f) =
        MissionItem(0, MissionItem.FRAME_MISSION, command, param1 = p1, param2 = p2, param3 = p3, param4 = p4)

    internal fun precision(p: PrecisionLand): Int = when (p) {
        PrecisionLand.DISABLED -> 0
        PrecisionLand.OPPORTUNISTIC -> 1
        PrecisionLand.REQUIRED -> 2
    }


    private val Location.latE7: Int get() = (latitude * 1e7).roundToLong().toInt()
    private val Location.lonE7: Int get() = (longitude * 1e7).roundToLong().toInt()


    /** Numbers items as they are added and remembers which step each belongs to. */
    private class Builder(private val flavor: MissionFlavor) {
        private val items = ArrayList<MissionItem>()
        private val stepOf = LinkedHashMap<Int, Int>()
        private val pending = ArrayList<Pair<Int, VehicleCommand>>()
        private val keyed = ArrayList<KeyedCommand>()

        fun add(step: Int?, item: MissionItem) {
            val seq = items.size
            flushCommands(seq)
            items += item.copy(seq = seq)
            if (step != null) stepOf[seq] = step
        }

        fun command(step: Int, command: VehicleCommand) {
            pending += step to command
        }

        private fun flushCommands(seq: Int) {
            pending.forEach { (step, command) -> keyed += KeyedCommand(seq, step, command) }
            pending.clear()
        }

        fun build(stepCount: Int, beforeStart: List<VehicleCommand>): MissionPlan {
            flushCommands(items.size)
            return MissionPlan(flavor, items.toList(), stepOf.toMap(), keyed.toList(), beforeStart, stepCount)
        }
    }
}
