package pod.sim.autopilot

import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Severity
import pod.mavlink.command.CommandResult
import kotlin.math.abs
import kotlin.math.sign
import kotlin.math.sqrt

/**
 * PX4's answer to MAV_CMD_DO_ORBIT (34), as COMMAND_LONG or COMMAND_INT: param1 radius in metres
 * (positive clockwise, negative counter-clockwise, NaN: unchanged), param2 speed along the circle
 * (NaN: unchanged), x/y the centre (NaN, or INT32_MAX in COMMAND_INT: unchanged), z its altitude
 * AMSL (NaN: unchanged). ArduPilot has no DO_ORBIT handler and answers UNSUPPORTED (the caller).
 */
internal class OrbitCommand(private val ap: FlightControl) {

    /**
     * Handles [cmd]; [refuse] explains a refusal before the ack, [report] queues a line that
     * follows it. Returns the COMMAND_ACK result.
     */
    fun handle(cmd: CommandRequest, refuse: (String) -> Unit, report: (String) -> Unit): CommandResult {
        // Commander.cpp, VEHICLE_CMD_DO_ORBIT: a fixed wing switches to Hold (AUTO_LOITER, "for
        // fixed wings the behavior of orbit is the same as loiter"), a multicopter to the orbit
        // mode. UserModeIntention::change allows any mode while disarmed; armed, the mode must be
        // able to run (ModeUtil/mode_requirements.cpp: ORBIT and AUTO_LOITER need a position
        // estimate). Refused: TEMPORARILY_REJECTED and "Orbit command rejected". Landed or
        // disarmed it is accepted: the mode changes and nothing flies (ORBIT then prevents arming).
        if (ap.armed && !ap.positionReady) {
            refuse("Orbit command rejected")
            return CommandResult.TEMPORARILY_REJECTED
        }
        // Airframe: PX4 orbits a multicopter in its own mode and loiters a fixed wing in Hold.
        if (ap.profile.rotorcraft) multicopter(cmd, report) else fixedWing(cmd)
        return CommandResult.ACCEPTED
    }

    /**
     * FlightTaskOrbit (src/modules/flight_mode_manager/tasks/Orbit/FlightTaskOrbit.cpp). Entering
     * the mode, activate() starts from radius 1 m, 1 m/s clockwise around the current position
     * and altitude; applyCommandParameters() then takes what the command gives and keeps the rest.
     */
    private fun multicopter(cmd: CommandRequest, report: (String) -> Unit) {
        val here = ap.body.location
        val previous = (ap.activity as? Activity.Orbit)?.takeIf { ap.modeName == ORBIT }
        if (ap.modeName != ORBIT) ap.setMode(ORBIT)
        if (!ap.flying) return // FlightModeManager re-activates the task until take-off: it stays down
        val start = previous ?: Activity.Orbit(here, RADIUS_MIN, clockwise = true, speed = 1.0)
        var clockwise = start.clockwise
        var radius = start.radius
        if (cmd.param1.isFinite()) {
            clockwise = cmd.param1 > 0
            radius = abs(cmd.param1.toDouble())
        }
        // The speed carries the direction; a negative param2 turns the other way.
        var velocity = (if (clockwise) 1.0 else -1.0) * (cmd.param2.takeIf { it.isFinite() }?.toDouble() ?: start.speed)
        if (radius !in RADIUS_MIN..ap.params["MC_ORBIT_RAD_MAX"]) {
            // applyCommandParameters fails: FlightModeManager::tryApplyCommandIfAny switches to the
            // failsafe task, which holds the position; Commander has already accepted the command
            // and the mode stays Orbit.
            report("Orbit radius limit exceeded")
            ap.fly(Activity.Hold(here, 0.0))
            return
        }
        // _sanitizeParams: the speed is limited to MPC_XY_VEL_MAX, then to a centripetal
        // acceleration below 2 m/s² (v² < 2·r); a small radius wins over a high speed.
        velocity = velocity.coerceIn(-ap.params["MPC_XY_VEL_MAX"], ap.params["MPC_XY_VEL_MAX"])
        if (velocity * velocity >= ACCELERATION_MAX * radius) velocity = velocity.sign * sqrt(ACCELERATION_MAX * radius)
        val lat = cmd.latitude()
        val lon = cmd.longitude()
        val center = if (lat != null && lon != null) Location(lat, lon, start.center.altitude) else start.center
        val alt = cmd.z.takeIf { it.isFinite() }?.toDouble() ?: center.altitude.meters
        ap.fly(Activity.Orbit(ap.at(center, alt), radius, clockwise = velocity > 0, speed = abs(velocity)))
    }

    /**
     * Navigator, VEHICLE_CMD_DO_ORBIT on a fixed wing (src/modules/navigator/navigator_main.cpp):
     * a loiter reposition around x/y (NaN: here) at z (NaN: current altitude), radius |param1| and
     * counter-clockwise when param1 < 0; param1 NaN keeps NAV_LOITER_RAD clockwise. A radius of 0
     * flies NAV_LOITER_RAD (FixedwingPositionControl, control_auto_loiter).
     */
    private fun fixedWing(cmd: CommandRequest) {
        if (ap.modeName != HOLD) ap.setMode(HOLD)
        if (!ap.flying) return // Navigator runs no mode while disarmed or landed
        val here = ap.body.location
        val lat = cmd.latitude() ?: here.latitude
        val lon = cmd.longitude() ?: here.longitude
        val alt = cmd.z.takeIf { it.isFinite() }?.toDouble() ?: here.altitude.meters
        val radius = cmd.param1.takeIf { it.isFinite() && abs(it) > 0f }?.let { abs(it).toDouble() } ?: ap.params["NAV_LOITER_RAD"]
        ap.fly(Activity.Hold(Location(lat, lon, alt.m), radius, clockwise = !(cmd.param1 < 0)))
    }

    companion object {
        /** PX4's name for the orbit mode (POSCTL main mode, ORBIT sub mode). */
        const val ORBIT = "POSCTL.ORBIT"
        private const val HOLD = "AUTO.LOITER"
        /** FlightTaskOrbit::_radius_min, m. */
        const val RADIUS_MIN = 1.0
        /** FlightTaskOrbit::_acceleration_max, the centripetal limit, m/s². */
        private const val ACCELERATION_MAX = 2.0
    }
}
