package pod.sim.autopilot

import pod.mavlink.command.CommandResult
import pod.core.vehicle.Severity
import pod.core.units.Location
import pod.mavlink.MavFrames
import pod.mavlink.MessageIds
import pod.core.units.m
import pod.mavlink.command.MavCommandParams.ARM_FORCE_MAGIC
import pod.mavlink.command.MavCommandParams.MODE_FLAG_CUSTOM_MODE_ENABLED
import pod.mavlink.command.MavCommandParams.REPOSITION_FLAG_CHANGE_MODE
import pod.mavlink.command.MavCommands.COMPONENT_ARM_DISARM
import pod.mavlink.command.MavCommands.DO_CHANGE_SPEED
import pod.mavlink.command.MavCommands.DO_LAND_START
import pod.mavlink.command.MavCommands.DO_ORBIT
import pod.mavlink.command.MavCommands.DO_PAUSE_CONTINUE
import pod.mavlink.command.MavCommands.DO_REPOSITION
import pod.mavlink.command.MavCommands.DO_SET_HOME
import pod.mavlink.command.MavCommands.DO_SET_MISSION_CURRENT
import pod.mavlink.command.MavCommands.DO_SET_MODE
import pod.mavlink.command.MavCommands.MISSION_START
import pod.mavlink.command.MavCommands.NAV_LAND
import pod.mavlink.command.MavCommands.NAV_LOITER_UNLIM
import pod.mavlink.command.MavCommands.NAV_RETURN_TO_LAUNCH
import pod.mavlink.command.MavCommands.NAV_TAKEOFF
import pod.mavlink.command.MavCommands.PREFLIGHT_CALIBRATION
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.command.CommandResult.ACCEPTED
import pod.mavlink.command.CommandResult.DENIED
import pod.mavlink.command.CommandResult.FAILED
import pod.mavlink.command.CommandResult.IN_PROGRESS
import pod.mavlink.command.CommandResult.TEMPORARILY_REJECTED
import pod.mavlink.command.CommandResult.UNSUPPORTED

/**
 * The vehicle side of the command protocol: each COMMAND_LONG / COMMAND_INT gets the COMMAND_ACK
 * result the claimed flavour would give in the vehicle's state (see docs/sim-vehicles.md for the
 * table and where each answer comes from). Long-running commands (PREFLIGHT_CALIBRATION) answer
 * IN_PROGRESS and finish from [step].
 */
internal class Commands(private val ap: SimAutopilot) {
    private var calibration: Calibration? = null
    private val orbit = OrbitCommand(ap)
    private val pauseContinue = PauseContinue(ap)

    /** Lines explaining the command being handled, sent with its ack in the flavour's order. */
    private val explanations = ArrayList<SimOutput.Text>()

    /** Lines from the part of the autopilot that acts on an accepted command, sent after its ack. */
    private val followUps = ArrayList<SimOutput.Text>()

    private class Calibration(val request: CommandRequest, var elapsed: Double = 0.0, var reported: Int = 0)

    /** Handles [cmd]; its ACK (and any STATUSTEXT) is queued on the autopilot. */
    fun handle(cmd: CommandRequest) {
        val result = when (cmd.command) {
            COMPONENT_ARM_DISARM -> armDisarm(cmd)
            DO_SET_MODE -> setMode(cmd.param1.toInt(), if (ap.isPx4) px4Mode(cmd.param2.toInt(), cmd.param3.toInt()) else cmd.param2.toLong())
            NAV_TAKEOFF -> takeoff(cmd)
            NAV_LAND -> land()
            NAV_RETURN_TO_LAUNCH -> modeResult(if (ap.isPx4) "AUTO.RTL" else "RTL")
            NAV_LOITER_UNLIM -> if (ap.isPx4 || !ap.multirotor) UNSUPPORTED else modeResult("LOITER")
            DO_LAND_START -> landStart()
            DO_REPOSITION -> reposition(cmd)
            DO_ORBIT -> if (ap.isPx4) orbit.handle(cmd, ::refuse) { followUps += SimOutput.Text(Severity.CRITICAL, it) } else UNSUPPORTED
            DO_PAUSE_CONTINUE -> pauseContinue.handle(cmd, ::refuse)
            MISSION_START -> missionStart(cmd)
            DO_SET_MISSION_CURRENT -> setCurrent(cmd)
            DO_CHANGE_SPEED -> if (!ap.isPx4 && cmd.param2 <= 0f) DENIED else changeSpeed(cmd.param1.toInt(), cmd.param2.toDouble())
            DO_SET_HOME -> setHome(cmd)
            PREFLIGHT_CALIBRATION -> calibrate(cmd)
            Geofence.DO_FENCE_ENABLE -> ap.fence.enableCommand(cmd)
            in CameraCommands.HANDLED -> CameraCommands.handle(ap, cmd)
            else -> UNSUPPORTED
        }
        ack(cmd, result, 0)
    }

    /** Handles the legacy SET_MODE message; ArduPilot acknowledges it as "command 11", PX4 as DO_SET_MODE. */
    fun handleSetMode(baseMode: Int, customMode: Long, sourceSystem: Int, sourceComponent: Int) {
        val result = setMode(baseMode, customMode)
        answer(SimOutput.Ack(if (ap.isPx4) DO_SET_MODE else MessageIds.SET_MODE, result, 0, sourceSystem, sourceComponent))
    }

    /** Advances long-running commands by [dt] seconds. */
    fun step(dt: Double) {
        val cal = calibration ?: return
        cal.elapsed += dt
        val percent = (cal.elapsed / CALIBRATION_SECONDS * 100).toInt().coerceAtMost(100)
        if (percent >= 100) {
            calibration = null
            ap.text(Severity.INFO, "Barometer calibration complete")
            ack(cal.request, ACCEPTED, 0)
        } else if (percent >= cal.reported + 25) {
            cal.reported = percent / 25 * 25
            ack(cal.request, IN_PROGRESS, cal.reported)
        }
    }

    private fun ack(cmd: CommandRequest, result: CommandResult, progress: Int) =
        answer(SimOutput.Ack(cmd.command, result, progress, cmd.sourceSystem, cmd.sourceComponent))

    /**
     * Queues [ack] and the lines explaining it. ArduPilot sends the COMMAND_ACK first and the text
     * after it: GCS_Common.cpp, GCS_MAVLINK::handle_command_long sends the ack as soon as the
     * handler returns, while GCS::send_textv only queues the STATUSTEXT for
     * GCS_MAVLINK::service_statustext to send on the next update_send pass. PX4 keeps the text
     * first (commander logs before it publishes the ack), so Pod is tested with both orders.
     */
    private fun answer(ack: SimOutput.Ack) {
        if (ap.isPx4) explanations.forEach(ap::emit)
        ap.emit(ack)
        if (!ap.isPx4) explanations.forEach(ap::emit)
        explanations.clear()
        followUps.forEach(ap::emit)
        followUps.clear()
    }

    private fun refuse(text: String) = refuse(text, Severity.CRITICAL)

    private fun refuse(text: String, severity: Severity) {
        explanations += SimOutput.Text(severity, text)
    }

    private fun armDisarm(cmd: CommandRequest): CommandResult {
        val forced = cmd.param2.toInt() == ARM_FORCE_MAGIC
        return when (cmd.param1.toInt()) {
            1 -> when {
                ap.armed -> ACCEPTED
                forced -> ACCEPTED.also { ap.arm() }
                else -> armingProblems().takeIf { it.isNotEmpty() }?.let { problems ->
                    problems.forEach { refuse(it) }
                    if (ap.isPx4) TEMPORARILY_REJECTED else FAILED
                } ?: ACCEPTED.also { ap.arm() }
            }
            0 -> when {
                !ap.armed -> ACCEPTED
                forced || !ap.flying -> ACCEPTED.also { ap.disarm() }
                ap.isPx4 -> TEMPORARILY_REJECTED.also { refuse("Disarming denied: not landed") }
                else -> FAILED
            }
            else -> DENIED
        }
    }

    /**
     * Every STATUSTEXT explaining why arming is refused now (empty when the vehicle may arm).
     * ArduPilot runs all its checks and reports each failure (AP_Arming::pre_arm_checks and
     * AP_Arming_Copter::run_pre_arm_checks chain them with `&`); PX4 reports the first.
     */
    fun armingProblems(): List<String> {
        val checks = if (ap.isPx4) px4ArmingChecks else arduPilotArmingChecks
        val failed = checks.mapNotNull { it() }
        return if (ap.isPx4) failed.take(1) else failed
    }

    private fun modeArmable(): Boolean =
        Modes.armable(ap.autopilot, ap.type, ap.modeName, if (ap.isPx4) 0 else ap.params.valueOf("AUTO_OPTIONS")?.toInt() ?: 0)

    private fun checksEnabled(): Boolean = ap.params["ARMING_CHECK"].toInt() != 0

    /** PX4's arming checks in the order commander reports them; a further check is one more entry. */
    private val px4ArmingChecks: List<() -> String?> = listOf(
        { "Arming denied: no valid global position estimate".takeIf { !ap.positionReady } },
        { "Arming denied: low battery".takeIf { ap.charge < ap.params["BAT_LOW_THR"] } },
        { "Arming denied: mode not armable".takeIf { !modeArmable() } },
        { "Arming denied: calibration in progress".takeIf { calibration != null } },
    )

    /**
     * ArduPilot's checks on an arm command, each the line it sends when it fails; a further check
     * is one more entry. The first two clear by waiting after boot, as on SITL (texts as ArduPilot
     * 4.7 SITL sent them): the inertial sensors' consistency (AP_Arming::ins_checks,
     * ins_accels_consistent) and home, which exists only once the EKF has an origin
     * (AP_Arming::gps_checks asks AP_AHRS::home_is_set: "AHRS: waiting for home"). An arm
     * command's failures start "Arm: " (AP_Arming::check_failed while arming).
     */
    private val arduPilotArmingChecks: List<() -> String?> = listOf(
        { "Arm: Accels inconsistent".takeIf { !ap.sensorsReady } },
        { "Arm: AHRS: waiting for home".takeIf { !ap.positionReady } },
        { "PreArm: Battery 1 below minimum arming voltage".takeIf { checksEnabled() && packVoltage(ap.charge) < ap.params["BATT_ARM_VOLT"] } },
        // ArduPlane names the mode (AP_Arming_Plane::pre_arm_checks: "%s %s" of the mode's name and
        // "mode not armable"; ModeRTL::_pre_arm_checks refuses): "Arm: RTL mode not armable".
        { (if (ap.multirotor) "Arm: Mode not armable" else "Arm: ${ap.modeName} mode not armable").takeIf { !modeArmable() } },
        { "Arm: DO_LAND_START set and RTL_AUTOLAND disabled".takeIf { checksEnabled() && planeLandStartRefused() } },
        { "PreArm: Calibration in progress".takeIf { calibration != null } },
        { ap.fence.armingProblem()?.let { "Arm: $it" } },
    )

    /**
     * ArduPlane will not arm a mission holding DO_LAND_START while RTL_AUTOLAND is 0, its default
     * (AP_Arming_Plane::mission_checks).
     */
    private fun planeLandStartRefused(): Boolean =
        !ap.multirotor && ap.params["RTL_AUTOLAND"].toInt() == 0 && ap.mission.landStartIndex() != null

    private fun px4Mode(main: Int, sub: Int): Long = (main.toLong() shl 16) or (sub.toLong() shl 24)

    private fun setMode(baseMode: Int, customMode: Long): CommandResult {
        if (baseMode and MODE_FLAG_CUSTOM_MODE_ENABLED == 0) return if (ap.isPx4) TEMPORARILY_REJECTED else UNSUPPORTED
        // PX4 Commander, VEHICLE_CMD_DO_SET_MODE: a POSCTL sub mode other than SLOW selects plain
        // POSCTL; only DO_ORBIT enters the orbit.
        val name = FlightModes.decode(ap.autopilot, ap.type, customMode).name.let { if (it == OrbitCommand.ORBIT) "POSCTL" else it }
        if (name.startsWith("MODE(") || (ap.isPx4 && name == "AUTO")) {
            if (ap.isPx4) refuse("Unsupported mode")
            return if (ap.isPx4) TEMPORARILY_REJECTED else FAILED
        }
        return modeResult(name)
    }

    /** Switches to [name] when the flavour allows it now: ACCEPTED, or the flavour's refusal. */
    private fun modeResult(name: String): CommandResult {
        val refused = if (ap.isPx4) TEMPORARILY_REJECTED else FAILED
        val behaviour = Modes.behaviour(ap.autopilot, ap.type, name) ?: return refused
        if (name == ap.modeName && behaviour != Behaviour.AUTO) return ACCEPTED
        if (behaviour == Behaviour.AUTO) {
            if (!ap.mission.hasMission()) {
                refuse(if (ap.isPx4) "Mission start denied! No valid mission" else "Mode change to AUTO failed: no mission")
                return refused
            }
            if (!ap.isPx4 && ap.multirotor && ap.armed && !ap.flying && !ap.mission.startsWithTakeoff()) {
                refuse("Auto: Missing Takeoff Cmd")
                return refused
            }
        }
        if (ap.isPx4 && name == "OFFBOARD") return refused.also { refuse("Offboard mode: no setpoints") }
        if (!ap.navigationReady && Modes.needsPosition(ap.autopilot, ap.type, name)) return refused.also { refuse("Mode change to $name failed: requires position") }
        ap.fence.refusesModeChange(name)?.let { (text, severity) -> return refused.also { refuse(text, severity) } }
        ap.setMode(name)
        return ACCEPTED
    }

    private fun takeoff(cmd: CommandRequest): CommandResult {
        if (ap.isPx4) {
            val amsl = cmd.z.takeIf { it.isFinite() }?.toDouble() ?: ap.takeoffAltitude(null)
            if (!ap.flying && !ap.positionReady) return TEMPORARILY_REJECTED.also { refuse("Takeoff denied! Please disarm and retry") }
            ap.setMode("AUTO.TAKEOFF")
            // Every NAV_TAKEOFF sets Navigator's takeoff setpoint to its altitude (PX4
            // navigator_main.cpp, VEHICLE_CMD_NAV_TAKEOFF -> get_takeoff_triplet()), a resend after a
            // lost ack too: re-entering AUTO.TAKEOFF above MIS_TAKEOFF_ALT must not end the climb.
            if (ap.activity is Activity.Takeoff || ap.flying) ap.activity = Activity.Takeoff(maxOf(amsl, ap.ground + 1.0), "AUTO.LOITER")
            return ACCEPTED
        }
        if (cmd.isInt && cmd.frame != MavFrames.GLOBAL_RELATIVE_ALT) return DENIED
        if (!ap.armed || ap.flying) return FAILED
        val altitude = ap.home.altitude.meters + cmd.z.toDouble()
        if (ap.multirotor) {
            if (ap.modeName !in setOf("GUIDED", "LOITER", "POSHOLD")) return FAILED
            ap.activity = Activity.Takeoff(altitude, null)
        } else {
            ap.setMode("TAKEOFF")
            ap.activity = Activity.Takeoff(if (cmd.z > 0) altitude else ap.takeoffAltitude(null), "LOITER")
        }
        return ACCEPTED
    }

    private fun land(): CommandResult = when {
        ap.isPx4 -> modeResult("AUTO.LAND")
        ap.multirotor -> modeResult("LAND")
        else -> UNSUPPORTED // ArduPlane lands through its mission's landing sequence (DO_LAND_START)
    }

    private fun landStart(): CommandResult {
        val index = ap.mission.landStartIndex() ?: return FAILED.also { refuse("No landing sequence found", Severity.WARNING) }
        if (!ap.flying) return FAILED
        ap.setMode(if (ap.isPx4) "AUTO.MISSION" else if (ap.multirotor) "AUTO_RTL" else "AUTO")
        ap.mission.startAt(index)
        return ACCEPTED
    }

    private fun reposition(cmd: CommandRequest): CommandResult {
        if (!ap.isPx4 && !cmd.isInt) return UNSUPPORTED // ArduPilot takes DO_REPOSITION only as COMMAND_INT
        val changeMode = cmd.param2.toInt() and REPOSITION_FLAG_CHANGE_MODE != 0
        val guided = if (ap.isPx4) "AUTO.LOITER" else "GUIDED"
        val arduPlane = !ap.isPx4 && !ap.multirotor
        // ArduCopter refuses outside GUIDED before it looks at the location (DENIED); ArduPlane
        // checks the location first and then answers FAILED (GCS_MAVLINK_Copter / _Plane
        // ::handle_command_int_do_reposition).
        if (!ap.isPx4 && !arduPlane && ap.modeName != guided && !changeMode) return DENIED
        val frame = cmd.frame ?: MavFrames.GLOBAL
        if (!MavFrames.isGlobal(frame)) return DENIED
        val lat = cmd.latitude()
        val lon = cmd.longitude()
        if ((lat != null && lat !in -90.0..90.0) || (lon != null && lon !in -180.0..180.0)) return DENIED
        if (arduPlane && ap.modeName != guided && !changeMode) return FAILED
        if (!ap.armed || !ap.flying) return if (ap.isPx4) TEMPORARILY_REJECTED else FAILED
        if (ap.isPx4 && !changeMode && ap.modeName != guided) return ACCEPTED // PX4 only acts on it in Hold
        val here = ap.body.location
        val alt = when {
            !cmd.z.isFinite() -> here.altitude.meters
            frame == MavFrames.GLOBAL || frame == MavFrames.GLOBAL_INT -> cmd.z.toDouble()
            else -> ap.home.altitude.meters + cmd.z
        }
        val target = Location(lat ?: here.latitude, lon ?: here.longitude, alt.m)
        if (!ap.fence.allowsDestination(target)) {
            // ArduPilot refuses it before any mode change; PX4 switches mode and acks but stays put.
            if (!ap.isPx4) return if (arduPlane) DENIED else FAILED
            if (ap.modeName != guided) ap.setMode(guided)
            return ACCEPTED.also { followUps += SimOutput.Text(Severity.CRITICAL, "Reposition is outside geofence") }
        }
        if (ap.modeName != guided) ap.setMode(guided)
        // ArduCopter flies to the point and stops there whatever param3/param4 say: its handler
        // passes only the location to ModeGuided::set_destination (ArduCopter/GCS_Mavlink.cpp,
        // GCS_MAVLINK_Copter::handle_command_int_do_reposition).
        ap.activity = if (arduPlane) planeGoTo(cmd, target) else Activity.GoTo(target, cmd.param1.toDouble().takeIf { it > 0 })
        return ACCEPTED
    }

    /**
     * ArduPlane in GUIDED flies to [target] and circles it (GCS_MAVLINK_Plane::
     * handle_command_int_do_reposition): param4 NaN or 0 means clockwise, anything else
     * counter-clockwise; Plane::set_guided_WP also turns counter-clockwise when WP_LOITER_RAD is
     * negative. A param3 > 0 sets GUIDED's radius and takes the direction from param4 alone
     * (ModeGuided::set_radius_and_direction); the radius stays until the plane leaves GUIDED, and
     * none (≤ 1 m) means WP_LOITER_RAD (Plane::update_loiter).
     */
    private fun planeGoTo(cmd: CommandRequest, target: Location): Activity.GoTo {
        val counterClockwise = !(cmd.param4.isNaN() || cmd.param4 == 0f)
        val loiterRad = ap.params["WP_LOITER_RAD"]
        val clockwise = if (cmd.param3 > 0f) {
            ap.guidedRadius = cmd.param3.toDouble().coerceAtMost(UINT16_MAX)
            !counterClockwise
        } else {
            !(counterClockwise || loiterRad < 0)
        }
        val radius = ap.guidedRadius.takeIf { it > 1.0 } ?: kotlin.math.abs(loiterRad)
        return Activity.GoTo(target, null, radius, clockwise, from = ap.body.location)
    }

    private fun missionStart(cmd: CommandRequest): CommandResult {
        if (ap.isPx4) {
            if (!ap.mission.hasMission()) return TEMPORARILY_REJECTED.also { refuse("Mission start denied! No valid mission") }
            val firstItem = cmd.param1.toInt()
            // PX4 Commander, VEHICLE_CMD_MISSION_START: param1 must be in -1 until the mission's seq_total.
            if (firstItem >= ap.missionServer.list(pod.mavlink.mission.MissionType.MISSION).size) return DENIED
            if (!ap.armed) {
                armingProblems().takeIf { it.isNotEmpty() }?.let { problems -> problems.forEach { refuse(it) }; return TEMPORARILY_REJECTED }
                ap.arm()
            }
            if (firstItem >= 0) ap.setCurrent(firstItem)
            ap.setMode("AUTO.MISSION")
            return ACCEPTED
        }
        if (cmd.param1 != 0f || cmd.param2 != 0f) return DENIED // first/last item are not supported
        return if (modeResult("AUTO") == ACCEPTED) ACCEPTED else FAILED
    }

    private fun setCurrent(cmd: CommandRequest): CommandResult {
        val seq = cmd.param1.toInt()
        if (seq !in 0 until ap.missionServer.list(pod.mavlink.mission.MissionType.MISSION).size) return DENIED
        ap.setCurrent(seq)
        // The same AP_Mission::set_current_cmd as MISSION_SET_CURRENT (GCS_MAVLINK::handle_command_do_set_mission_current).
        if (!ap.isPx4 && ap.activity == Activity.Mission) ap.mission.restart()
        return ACCEPTED
    }

    /** DO_CHANGE_SPEED: [kind] 0 air / 1 ground / 2 climb / 3 descent, [speed] m/s (-1 or less: unchanged). */
    fun changeSpeed(kind: Int, speed: Double): CommandResult {
        if (speed <= 0) return ACCEPTED
        when (kind) {
            0, 1 -> ap.cruiseOverride = speed
            2 -> ap.climbOverride = speed
            3 -> ap.descentOverride = speed
            else -> return DENIED
        }
        return ACCEPTED
    }

    private fun setHome(cmd: CommandRequest): CommandResult {
        if (cmd.param1.toInt() == 1) {
            ap.setHome(ap.body.location)
            return ACCEPTED
        }
        val lat = cmd.latitude() ?: return FAILED
        val lon = cmd.longitude() ?: return FAILED
        if (lat !in -90.0..90.0 || lon !in -180.0..180.0 || (lat == 0.0 && lon == 0.0)) return FAILED
        val alt = if (cmd.frame == MavFrames.GLOBAL_RELATIVE_ALT || cmd.frame == MavFrames.GLOBAL_RELATIVE_ALT_INT) ap.home.altitude.meters + cmd.z else cmd.z.toDouble()
        ap.setHome(Location(lat, lon, alt.m))
        return ACCEPTED
    }

    private fun calibrate(cmd: CommandRequest): CommandResult {
        if (ap.armed || calibration != null) return TEMPORARILY_REJECTED
        val any = listOf(cmd.param1, cmd.param2, cmd.param3, cmd.param4, cmd.x.toFloat(), cmd.y.toFloat(), cmd.z).any { it != 0f }
        if (!any) return ACCEPTED
        calibration = Calibration(cmd)
        return IN_PROGRESS
    }

    companion object {
        const val CALIBRATION_SECONDS = 2.0
        private const val UINT16_MAX = 65535.0
    }
}
