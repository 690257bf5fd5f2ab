package pod.mavlink.queue

import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.VehicleType
import pod.mavlink.MavFrames
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.MavCommandParams.REPOSITION_FLAG_CHANGE_MODE
import pod.mavlink.command.MavCommands.DO_ORBIT
import pod.mavlink.command.MavCommands.DO_REPOSITION
import pod.mavlink.command.VehicleCommand
import pod.mavlink.firmware.Firmware
import kotlin.math.PI
import kotlin.math.atan2
import kotlin.math.cos
import kotlin.math.sin

/**
 * How a queue flight steers one vehicle outside any mission: every change is one acknowledged
 * command, so a change the link loses leaves the vehicle flying the old element, never half of a
 * new one. Targets are absolute (altitude above sea level), as DO_REPOSITION takes them.
 *
 * Per autopilot (sources checked, see docs/mission-queue.md):
 * - a point: DO_REPOSITION as COMMAND_INT with the change-mode flag, which switches an ArduPilot
 *   vehicle to GUIDED and a PX4 one to Hold (AUTO.LOITER) by itself (ArduCopter/GCS_Mavlink.cpp and
 *   ArduPlane/GCS_Mavlink.cpp handle_command_int_do_reposition; PX4 navigator's DO_REPOSITION);
 * - a circle on an ArduPlane: the same DO_REPOSITION with param3 the radius and param4 non-zero for
 *   counter-clockwise (ArduPlane handle_command_int_do_reposition → mode_guided.set_radius_and_direction);
 * - a circle on PX4, multicopter or plane: DO_ORBIT, radius signed as Pod's (positive clockwise;
 *   Commander switches a multicopter to the orbit mode POSCTL.ORBIT, a plane to a loiter around the
 *   point in AUTO.LOITER), with the speed given (the multicopter orbit starts at 1 m/s otherwise);
 * - a circle on an ArduCopter: GUIDED has no orbit and its CIRCLE mode puts the centre ahead of the
 *   vehicle (AC_Circle::init), so the ground flies it: a target on the circle a little ahead of the
 *   vehicle, moved every step ([Carrots.onCircle]).
 */
internal class GuidedSteering(private val vehicle: MavlinkVehicle, private val circleSpeed: Double) {
    /**
     * The loiter radius a plane circles a reached point at, sent with every point: ArduPlane keeps
     * the radius of the last DO_REPOSITION that gave one for as long as it stays in GUIDED
     * (ModeGuided::_enter resets it only on entry), so after a circle a plain point would be circled
     * at the circle's radius. Null: leave it to the autopilot.
     */
    var planeLoiterRadius: Distance? = null

    private val firmware: Firmware get() = Firmware.of(vehicle.identity.value)
    private val type: VehicleType get() = vehicle.identity.value.type

    val isPlane: Boolean get() = type == VehicleType.FIXED_WING || type == VehicleType.VTOL

    /** Whether circles are flown from the ground, target by target (ArduCopter). */
    val circlesFromGround: Boolean get() = !firmware.orbitsOnCommand && !isPlane

    /** Flies to [target] and holds there (a plane circles it at its default loiter radius). */
    suspend fun goTo(target: Location) {
        vehicle.commands.send(reposition(target))
    }

    /** Circles [center] at [radius], positive clockwise, where the autopilot can do it alone. */
    suspend fun circle(center: Location, radius: Distance) {
        val command = when {
            // PX4's multicopter orbit starts at 1 m/s unless told (FlightTaskOrbit::activate), and
            // caps the speed itself (MPC_XY_VEL_MAX, v² < 2r).
            firmware.orbitsOnCommand -> VehicleCommand(
                DO_ORBIT,
                param1 = radius.meters.toFloat(),
                param2 = circleSpeed.toFloat(),
                param3 = Float.NaN,
                param4 = Float.NaN,
                param5 = center.latitude, param6 = center.longitude, param7 = center.altitude.meters.toFloat(),
                frame = MavFrames.GLOBAL_INT,
            )
            isPlane -> reposition(center).copy(
                param3 = kotlin.math.abs(radius.meters).toFloat(),
                param4 = if (radius.meters < 0) 1f else 0f,
            )
            else -> error("an ArduCopter circle is flown from the ground (Carrots.onCircle)")
        }
        vehicle.commands.send(command)
    }

    private fun reposition(target: Location) = VehicleCommand(
        DO_REPOSITION,
        param1 = -1f,
        param2 = REPOSITION_FLAG_CHANGE_MODE.toFloat(),
        param3 = if (isPlane && firmware.repositionTakesLoiterRadius) planeLoiterRadius?.meters?.toFloat() ?: 0f else 0f,
        param4 = Float.NaN,
        param5 = target.latitude, param6 = target.longitude, param7 = target.altitude.meters.toFloat(),
        frame = MavFrames.GLOBAL_INT,
    )
}

/**
 * Targets the ground moves ahead of a vehicle to make it follow a shape its autopilot will not fly
 * by itself from a guided mode: a circle around a given centre (ArduCopter), and a straight leg for
 * a plane (which flies straight at a guided point from wherever it is, so a leg joined off its
 * start would be flown askew). Pure geometry; the caller moves the target every step.
 */
internal object Carrots {
    /** The target on the circle around [center] (radius signed, positive clockwise) for a vehicle at [here], [lead] radians ahead. */
    fun onCircle(center: Location, radius: Distance, here: Location, lead: Double): Location {
        val (north, east) = northEast(center, here)
        val bearing = if (north == 0.0 && east == 0.0) 0.0 else atan2(east, north)
        val step = if (radius.meters > 0) lead else -lead
        val r = kotlin.math.abs(radius.meters)
        val angle = bearing + step
        return center.offset((r * cos(angle)).m, (r * sin(angle)).m)
    }

    /** The lead angle (radians) for a vehicle flying [speed] m/s on a circle of [radius]: about [ahead] seconds, at most 60°. */
    fun lead(radius: Distance, speed: Double, ahead: Double): Double =
        (speed * ahead / kotlin.math.abs(radius.meters)).coerceIn(0.2, PI / 3)

    /**
     * The target on the leg [from]–[to] [lookahead] beyond the vehicle's projection onto it (at
     * [to] once that is nearer), at [to]'s altitude.
     */
    fun onLine(from: Location, to: Location, here: Location, lookahead: Distance): Location {
        val (ln, le) = northEast(from, to)
        val length = kotlin.math.hypot(ln, le)
        if (length < 1.0) return to
        val (hn, he) = northEast(from, here)
        val along = ((hn * ln + he * le) / length).coerceAtLeast(0.0) + lookahead.meters
        if (along >= length) return to
        return from.offset((ln * along / length).m, (le * along / length).m).copy(altitude = to.altitude)
    }

    private fun northEast(from: Location, to: Location): Pair<Double, Double> =
        from.northEastTo(to).let { (n, e) -> n.meters to e.meters }
}
