package pod.sim.autopilot

import pod.mavlink.command.CommandResult
import pod.core.vehicle.Severity
import pod.core.units.Location
import pod.mavlink.MavFrames
import pod.core.units.m
import pod.mavlink.command.MavCommandParams.ARM_FORCE_MAGIC
import pod.mavlink.command.MavCommandParams.MODE_FLAG_CUSTOM_MODE_ENABLED
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
import pod.sim.autopilot.profile.ArmingView

/**
 * The vehicle side of the command protocol: each COMMAND_LONG / COMMAND_INT gets the COMMAND_ACK
 * result its profile's firmware would give in the vehicle's state (see docs/sim-vehicles.md for
 * the table and where each answer comes from). Long-running commands (PREFLIGHT_CALIBRATION)
 * answer IN_PROGRESS and finish from [step]; the guided-flight commands are [GuidedCommands]'.
 */
internal class Commands(private val ap: FlightControl) {
    private val profile get() = ap.profile
    private var calibration: Calibration? = null
    private val orbit = OrbitCommand(ap)
    private val pauseContinue = PauseContinue(ap)
    private val replies = object : CommandReplies {
        override fun refuse(text: String, severity: Severity) = this@Commands.refuse(text, severity)
        override fun modeResult(name: String) = this@Commands.modeResult(name)
        override fun armingProblems() = this@Commands.armingProblems()
        override fun followUp(text: String) {
            followUps += SimOutput.Text(Severity.CRITICAL, text)
        }
    }
    private val guided = GuidedCommands(ap, replies)

    /** Lines explaining the command being handled, sent with its ack in the profile's order. */
    private val explanations = ArrayList<SimOutput.Text>()

    /** Lines from the part of the autopilot that acts on an accepted command, sent after its ack. */
    private val followUps = ArrayList<SimOutput.Text>()

    private class Calibration(val request: CommandRequest, var elapsed: Double = 0.0, var reported: Int = 0)

    /** Handles [cmd]; its ACK (and any STATUSTEXT) is queued on the autopilot. */
    fun handle(cmd: CommandRequest) {
        val result = when (cmd.command) {
            COMPONENT_ARM_DISARM -> armDisarm(cmd)
            DO_SET_MODE -> setMode(cmd.param1.toInt(), profile.setModeCustomMode(cmd.param2, cmd.param3))
            NAV_TAKEOFF -> guided.takeoff(cmd)
            NAV_LAND -> profile.landMode?.let { modeResult(it) } ?: UNSUPPORTED
            NAV_RETURN_TO_LAUNCH -> modeResult(profile.returnMode)
            NAV_LOITER_UNLIM -> profile.loiterUnlimitedMode?.let { modeResult(it) } ?: UNSUPPORTED
            DO_LAND_START -> guided.landStart()
            DO_REPOSITION -> guided.reposition(cmd)
            DO_ORBIT -> if (profile.handlesOrbit) orbit.handle(cmd, ::refuse, replies::followUp) else UNSUPPORTED
            DO_PAUSE_CONTINUE -> pauseContinue.handle(cmd, ::refuse)
            MISSION_START -> guided.missionStart(cmd)
            DO_SET_MISSION_CURRENT -> guided.setCurrent(cmd)
            DO_CHANGE_SPEED -> if (profile.changeSpeedNeedsSpeed && cmd.param2 <= 0f) DENIED else changeSpeed(cmd.param1.toInt(), cmd.param2.toDouble())
            DO_SET_HOME -> setHome(cmd)
            PREFLIGHT_CALIBRATION -> calibrate(cmd)
            Geofence.DO_FENCE_ENABLE -> ap.fence.enableCommand(cmd)
            in CameraCommands.HANDLED -> CameraCommands.handle(ap, cmd)
            else -> UNSUPPORTED
        }
        ack(cmd, result, 0)
    }

    /** Handles the legacy SET_MODE message, acknowledged with the profile's command id. */
    fun handleSetMode(baseMode: Int, customMode: Long, sourceSystem: Int, sourceComponent: Int) {
        val result = setMode(baseMode, customMode)
        answer(SimOutput.Ack(profile.setModeMessageAck, result, 0, sourceSystem, sourceComponent))
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

    /** Queues [ack] and the lines explaining it, in the profile's order ([pod.sim.autopilot.profile.AutopilotProfile.textBeforeAck]). */
    private fun answer(ack: SimOutput.Ack) {
        if (profile.textBeforeAck) explanations.forEach(ap::emit)
        ap.emit(ack)
        if (!profile.textBeforeAck) explanations.forEach(ap::emit)
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
                    profile.refusal
                } ?: ACCEPTED.also { ap.arm() }
            }
            0 -> when {
                !ap.armed -> ACCEPTED
                forced || !ap.flying -> ACCEPTED.also { ap.disarm() }
                else -> profile.refusal.also { profile.disarmInFlightText?.let { refuse(it) } }
            }
            else -> DENIED
        }
    }

    /** Every STATUSTEXT explaining why arming is refused now (empty when the vehicle may arm), as the profile reports them. */
    fun armingProblems(): List<String> = profile.armingRefusals(armingView)

    private val armingView = object : ArmingView {
        override val positionReady get() = ap.positionReady
        override val sensorsReady get() = ap.sensorsReady
        override val charge get() = ap.charge
        override val params get() = ap.params
        override val modeName get() = ap.modeName
        override val calibrating get() = calibration != null
        override val fenceArmingProblem get() = ap.fence.armingProblem()
        override val hasLandStart get() = ap.mission.landStartIndex() != null
    }

    private fun setMode(baseMode: Int, customMode: Long): CommandResult {
        if (baseMode and MODE_FLAG_CUSTOM_MODE_ENABLED == 0) return profile.setModeWithoutCustomFlag
        val decoded = FlightModes.decode(profile.autopilot, ap.type, customMode).name
        val name = profile.selectableMode(decoded) ?: run {
            profile.unknownModeText?.let { refuse(it) }
            return profile.refusal
        }
        return modeResult(name)
    }

    /** Switches to [name] when the profile allows it now: ACCEPTED, or the profile's refusal. */
    private fun modeResult(name: String): CommandResult {
        val refused = profile.refusal
        val behaviour = profile.behaviour(name) ?: return refused
        if (name == ap.modeName && behaviour != Behaviour.AUTO) return ACCEPTED
        if (behaviour == Behaviour.AUTO) {
            if (!ap.mission.hasMission()) {
                refuse(profile.noMissionText)
                return refused
            }
            if (profile.autoNeedsTakeoffItemOnGround && ap.armed && !ap.flying && !ap.mission.startsWithTakeoff()) {
                refuse("Auto: Missing Takeoff Cmd")
                return refused
            }
        }
        profile.modeRefusalText(name)?.let { return refused.also { _ -> refuse(it) } }
        if (!ap.navigationReady && profile.needsPosition(name)) return refused.also { refuse("Mode change to $name failed: requires position") }
        ap.fence.refusesModeChange(name)?.let { (text, severity) -> return refused.also { refuse(text, severity) } }
        ap.setMode(name)
        return ACCEPTED
    }

    /** DO_CHANGE_SPEED: [kind] 0 air / 1 ground / 2 climb / 3 descent, [speed] m/s (-1 or less: unchanged). */
    fun changeSpeed(kind: Int, speed: Double): CommandResult = if (ap.speeds.change(kind, speed)) ACCEPTED else DENIED

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
    }
}
