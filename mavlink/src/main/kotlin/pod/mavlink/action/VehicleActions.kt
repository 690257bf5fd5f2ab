package pod.mavlink.action

import io.dronefleet.mavlink.common.MavMode
import io.dronefleet.mavlink.common.SetMode
import io.dronefleet.mavlink.util.EnumValue
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.Speed
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.LandedState
import pod.core.vehicle.isAirborne
import pod.core.vehicle.isOnGround
import pod.core.vehicle.VehicleLost
import pod.core.vehicle.VehicleType
import pod.mavlink.MavFrames
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.CommandResult
import pod.mavlink.command.MavCommandParams.ARM_FORCE_MAGIC
import pod.mavlink.command.MavCommandParams.MODE_FLAG_CUSTOM_MODE_ENABLED
import pod.mavlink.command.MavCommandParams.REPOSITION_FLAG_CHANGE_MODE
import pod.mavlink.command.MavCommands.COMPONENT_ARM_DISARM
import pod.mavlink.command.MavCommands.DO_CHANGE_SPEED
import pod.mavlink.command.MavCommands.DO_LAND_START
import pod.mavlink.command.MavCommands.DO_PAUSE_CONTINUE
import pod.mavlink.command.MavCommands.DO_REPOSITION
import pod.mavlink.command.MavCommands.DO_SET_HOME
import pod.mavlink.command.MavCommands.DO_SET_MODE
import pod.mavlink.command.MavCommands.MISSION_START
import pod.mavlink.command.MavCommands.NAV_LAND
import pod.mavlink.command.MavCommands.NAV_RETURN_TO_LAUNCH
import pod.mavlink.command.MavCommands.NAV_TAKEOFF
import pod.mavlink.command.MavCommands.SET_MESSAGE_INTERVAL
import pod.mavlink.command.SpeedTypes
import pod.core.mission.SpeedKind
import pod.mavlink.command.VehicleCommand
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.telemetry.ModeRole

/**
 * What a ground-station operator does to one vehicle, each step confirmed: the command's
 * acknowledgement and, where it matters, the state the vehicle then reports (armed, mode,
 * altitude). Each call returns once confirmed and throws otherwise:
 * [pod.mavlink.command.CommandException] when the vehicle refused or never answered,
 * [ActionException] when it answered but did not do it, [VehicleLost] when it fell silent.
 *
 * Modes are picked per autopilot and airframe ([FlightModes.forRole]): hold is BRAKE on an
 * ArduCopter, LOITER on an ArduPlane and AUTO.LOITER on PX4, never a mode in which a multicopter
 * without stick input would sink (ArduCopter's LOITER does).
 */
public class VehicleActions internal constructor(private val vehicle: MavlinkVehicle) {
    @Volatile private var pausedByCommand: Boolean? = null
    private val _waitingFor = MutableStateFlow<String?>(null)

    /** How long a state change (armed flag, mode) may take to show in telemetry after the ack. */
    public var confirmTimeout: Duration = 8.seconds

    /**
     * How long [arm] waits for a vehicle that is still initialising. Real autopilots take tens of
     * seconds after boot: ArduCopter SITL arms ~43 s after boot, ArduPlane ~23 s.
     */
    public var readyTimeout: Duration = 90.seconds

    /**
     * What [arm] is waiting for now, in the autopilot's words ("Arm: AHRS: waiting for home"), or
     * null when it is not waiting: for a UI or a log to show while a vehicle initialises.
     */
    public val waitingFor: StateFlow<String?> = _waitingFor.asStateFlow()

    /**
     * Arms the motors ([force] skips the autopilot's pre-arm checks) and waits until telemetry shows
     * it armed. A vehicle still initialising (its refusal names the estimator, home, GPS or settling
     * sensors) is asked again every second for up to [readyTimeout], with [waitingFor] saying
     * why; then [VehicleNotReady]. A refusal waiting cannot clear (battery, mode) fails at once with
     * the autopilot's reason ([CommandRejected]).
     */
    public suspend fun arm(force: Boolean = false) {
        retryWhileInitialising("arm", { ArmReadiness.waitFor(it.statusTexts, initialising()) }) {
            command(VehicleCommand(COMPONENT_ARM_DISARM, param1 = 1f, param2 = if (force) ARM_FORCE_MAGIC.toFloat() else 0f))
        }
        confirm("arm", "armed", vehicle.telemetry.armed) { it }
    }

    /** What the vehicle's own reports say about it still booting: no home, no 3D fix, or a booting heartbeat. */
    private fun initialising(): Boolean {
        val t = vehicle.telemetry
        val status = t.systemStatus.value
        return t.home.value == null || (t.gps.value?.let { it.fixType < GPS_FIX_3D } ?: false) ||
            status == MAV_STATE_UNINIT || status == MAV_STATE_BOOT || status == MAV_STATE_CALIBRATING
    }

    /** Disarms the motors ([force] even in flight, which drops a multicopter) and waits until telemetry shows it. */
    public suspend fun disarm(force: Boolean = false) {
        command(VehicleCommand(COMPONENT_ARM_DISARM, param1 = 0f, param2 = if (force) ARM_FORCE_MAGIC.toFloat() else 0f))
        confirm("disarm", "disarmed", vehicle.telemetry.armed) { !it }
    }

    /**
     * Switches to the mode called [name] ("GUIDED", "AUTO", "AUTO.MISSION" on PX4, …) and waits
     * until the heartbeat reports it. Throws [UnknownMode] for a name the vehicle does not have. A
     * refusal that clears once the estimator has a position (ArduCopter's "Mode change to GUIDED
     * failed: requires position" after boot) is waited out like [arm]'s, with [waitingFor] saying
     * why, for up to [readyTimeout]; then [VehicleNotReady].
     */
    public suspend fun setMode(name: String) {
        val (autopilot, type) = airframe()
        val custom = FlightModes.customMode(autopilot, type, name)
            ?: throw UnknownMode(name, autopilot, type, FlightModes.names(autopilot, type))
        if (vehicle.telemetry.mode.value?.customMode == custom) return
        val command = if (autopilot == Autopilot.PX4) {
            VehicleCommand(DO_SET_MODE, param1 = MODE_FLAG_CUSTOM_MODE_ENABLED.toFloat(), param2 = ((custom shr 16) and 0xFF).toFloat(), param3 = ((custom shr 24) and 0xFF).toFloat())
        } else {
            VehicleCommand(DO_SET_MODE, param1 = MODE_FLAG_CUSTOM_MODE_ENABLED.toFloat(), param2 = custom.toFloat())
        }
        try {
            retryWhileInitialising("switch to $name", { ArmReadiness.modeWaitFor(it.statusTexts, initialising()) }) { command(command) }
        } catch (e: CommandRejected) {
            if (e.result != CommandResult.UNSUPPORTED) throw e
            // Autopilots older than DO_SET_MODE take the (unacknowledged) SET_MODE message.
            vehicle.send(SetMode.builder().targetSystem(vehicle.systemId).baseMode(EnumValue.create<MavMode>(1)).customMode(custom).build())
        }
        confirm("set mode $name", "mode $name", vehicle.telemetry.mode) { it?.customMode == custom }
    }

    /**
     * Runs [attempt] again every [ARM_RETRY] while the vehicle refuses it with a reason that clears
     * by waiting ([waitFor] names it; null: it will not), showing the reason in [waitingFor], for
     * up to [readyTimeout] in all; then [VehicleNotReady]. Other refusals are thrown as they are.
     */
    private suspend fun retryWhileInitialising(action: String, waitFor: (CommandRejected) -> String?, attempt: suspend () -> Unit) {
        val started = vehicle.clock.markNow()
        try {
            while (true) {
                try {
                    attempt()
                    return
                } catch (e: CommandRejected) {
                    val reason = waitFor(e) ?: throw e
                    if (started.elapsedNow() + ARM_RETRY > readyTimeout) throw VehicleNotReady(vehicle.systemId, reason, readyTimeout, action)
                    _waitingFor.value = reason
                    delay(ARM_RETRY)
                }
            }
        } finally {
            _waitingFor.value = null
        }
    }

    /**
     * Takes off to [altitude] above home and waits until it is reached (within 5 %, at least
     * 1 m) or [timeout] passes. The vehicle must be armed ([VehicleDisarmed] otherwise, before
     * anything changes) and stay so ([DisarmedDuring] as soon as it disarms). ArduPilot copters switch to GUIDED
     * first; ArduPilot planes use TAKEOFF mode with TKOFF_ALT; PX4 takes NAV_TAKEOFF to an
     * altitude above sea level, computed from home.
     */
    public suspend fun takeoff(altitude: Distance, timeout: Duration = 2.minutes) {
        require(altitude.meters > 0 && altitude.meters <= 10_000) { "altitude must be in (0, 10000] m, was $altitude" }
        // PX4 accepts NAV_TAKEOFF disarmed and sits in Takeoff mode on the ground (commander's
        // VEHICLE_CMD_NAV_TAKEOFF only changes the mode; it never arms), and ArduCopter refuses it
        // with a bare FAILED (Mode::do_user_takeoff): say so before changing anything.
        requireArmed("take off")
        val (autopilot, type) = airframe()
        when {
            autopilot == Autopilot.PX4 -> {
                val home = awaitHomeAltitude()
                command(VehicleCommand(NAV_TAKEOFF, param4 = Float.NaN, param5 = Double.NaN, param6 = Double.NaN, param7 = (home + altitude.meters).toFloat()))
            }
            isPlane(type) -> {
                vehicle.params.write("TKOFF_ALT", altitude.meters)
                setMode(role(ModeRole.TAKEOFF))
            }
            else -> {
                setMode(role(ModeRole.GUIDED))
                try {
                    command(VehicleCommand(NAV_TAKEOFF, param7 = altitude.meters.toFloat()))
                } catch (e: CommandRejected) {
                    // A resend after a lost ack is refused by a copter already climbing: that is success.
                    if (e.attempts == 1 || !leavingGround()) throw e
                }
            }
        }
        val tolerance = maxOf(1.0, altitude.meters * 0.05)
        confirm("takeoff to $altitude", "altitude ≥ ${altitude.meters - tolerance} m", vehicle.telemetry.position, timeout, untilDisarmed = true, describe = ::heightText) {
            it != null && it.relativeAltitude.meters >= altitude.meters - tolerance
        }
    }

    /**
     * Gets the vehicle into the air at [height] above home from whatever state it was left in
     * (freshly booted, just landed, left in RTL, LAND, BRAKE or AUTO): nothing when it already
     * flies; otherwise into its take-off mode first (GUIDED on an ArduCopter; out of a mode it will
     * not arm in on ArduPlane and PX4), waiting out refusals that clear by waiting, then armed and
     * taken off ([takeoff]). Returns what it changed, in order ("mode STABILIZE → GUIDED",
     * "armed", "took off to 20.0 m"); empty when it was already flying.
     */
    public suspend fun getAirborne(height: Distance, timeout: Duration = 2.minutes): List<String> {
        require(height.meters > 0 && height.meters <= 10_000) { "altitude must be in (0, 10000] m, was $height" }
        return GettingAirborne(vehicle, this).takeOff(height, timeout)
    }

    /**
     * Arms a vehicle on the ground for a flight that changes mode itself (a mission start), from
     * whatever mode it was left in: into [mode] first, or, when null, out of a mode the autopilot
     * will not arm in ("Arm: Mode not armable" in AUTO, RTL, LAND, BRAKE; PX4 in Land or Return)
     * into its hold mode. Returns what it changed; empty when it was armed already.
     */
    public suspend fun armForFlight(mode: String? = null): List<String> =
        if (vehicle.telemetry.armed.value) emptyList() else GettingAirborne(vehicle, this).armOnGround(mode)

    /**
     * Whether the vehicle is off the ground: its landed state, or, while that is unknown
     * (UNDEFINED until EXTENDED_SYS_STATE is streamed), its arming state and height above home,
     * after giving a freshly heard vehicle's reports a moment to arrive.
     */
    public suspend fun isFlying(): Boolean = GettingAirborne(vehicle, this).flying()

    /**
     * Lands: a multicopter where it is (NAV_LAND, confirmed by the LAND mode); an ArduPilot plane
     * through its mission's landing sequence (DO_LAND_START, confirmed by AUTO), or, when its
     * mission has none, at home after the approach the mission executor plans ([PlaneLanding]:
     * uploaded in place of the mission on board). Returns when the landing has begun;
     * [awaitLanded] waits for touchdown.
     */
    public suspend fun land() {
        val (autopilot, type) = airframe()
        if (autopilot != Autopilot.PX4 && isPlane(type)) {
            try {
                command(VehicleCommand(DO_LAND_START))
            } catch (e: CommandRejected) {
                if (e.statusTexts.none { it.contains("No landing sequence", ignoreCase = true) }) throw e
                PlaneLanding.plan(vehicle)
                setMode(role(ModeRole.MISSION))
            }
            confirmMode("land", ModeRole.MISSION)
        } else {
            command(VehicleCommand(NAV_LAND, param4 = Float.NaN, param5 = Double.NaN, param6 = Double.NaN))
            confirmMode("land", ModeRole.LAND)
        }
    }

    /** Returns to launch (NAV_RETURN_TO_LAUNCH), confirmed by the return mode. */
    public suspend fun returnToLaunch() {
        command(VehicleCommand(NAV_RETURN_TO_LAUNCH))
        confirmMode("return to launch", ModeRole.RETURN)
    }

    /**
     * Flies to [target] (altitude above sea level) and holds there, at [speed] or the vehicle's
     * own: DO_REPOSITION as COMMAND_INT (ArduPilot takes it only in that form), switching to the
     * guided mode first. Returns once accepted; [awaitArrival] waits until it is there.
     */
    public suspend fun goto(target: Location, speed: Speed? = null) {
        // Before the mode change: a disarmed ArduCopter would be left in GUIDED and then refuse
        // the reposition with a bare FAILED.
        requireArmed("fly to a point")
        val guided = role(ModeRole.GUIDED)
        if (airframe().first != Autopilot.PX4) setMode(guided)
        command(
            VehicleCommand(
                DO_REPOSITION,
                param1 = speed?.metersPerSecond?.toFloat() ?: -1f,
                param2 = REPOSITION_FLAG_CHANGE_MODE.toFloat(),
                param4 = Float.NaN,
                param5 = target.latitude, param6 = target.longitude, param7 = target.altitude.meters.toFloat(),
                frame = MavFrames.GLOBAL_INT,
            ),
        )
        confirm("goto", "mode $guided", vehicle.telemetry.mode) { it?.name == guided }
    }

    /**
     * Stops and holds position and altitude without needing anyone on the sticks, and waits until
     * the heartbeat shows the mode: BRAKE on an ArduCopter, AUTO.LOITER on PX4; a plane circles
     * where it is (ArduPlane LOITER). See [FlightModes.forRole] for the autopilots' sources.
     */
    public suspend fun hold() {
        val hold = role(ModeRole.HOLD)
        val here = vehicle.telemetry.position.value
        // PX4's Hold is also where a goto flies (DO_REPOSITION in AUTO.LOITER), and choosing the
        // mode a vehicle is already in changes nothing: a reposition stops it there (PX4
        // src/modules/navigator/loiter.cpp Loiter::on_active -> reposition()). Onto where it can
        // stop, not where it was heard: that point is behind a moving vehicle by its braking distance.
        if (hold == role(ModeRole.GUIDED) && vehicle.telemetry.mode.value?.name == hold && vehicle.telemetry.armed.value && here != null) {
            goto(StoppingPoint.of(here))
            return
        }
        setMode(hold)
    }

    /**
     * Pauses the mission where the vehicle is, holding position and altitude: with
     * DO_PAUSE_CONTINUE where the autopilot supports it (ArduCopter), by switching to the hold
     * mode otherwise. [continueMission] resumes at the same item either way. A vehicle disarmed on
     * the ground has nothing to pause ([NothingInFlight], nothing sent).
     */
    public suspend fun pauseMission() {
        if (!vehicle.telemetry.armed.value) throw NothingInFlight(vehicle.systemId, "pause")
        try {
            command(VehicleCommand(DO_PAUSE_CONTINUE, param1 = 0f))
            pausedByCommand = true
        } catch (e: CommandRejected) {
            when {
                e.result == CommandResult.UNSUPPORTED -> {
                    hold()
                    pausedByCommand = false
                }
                // ArduCopter fails a pause when already paused: after a lost ack, the first send did it.
                e.result == CommandResult.FAILED && e.attempts > 1 -> pausedByCommand = true
                else -> throw e
            }
        }
    }

    /**
     * Resumes what [pauseMission] paused, by this process or another: a mission at the item it was
     * on, or an ArduCopter's goto in GUIDED, which flies on to its destination. An ArduCopter in
     * AUTO or GUIDED is resumed with DO_PAUSE_CONTINUE (ModeAuto::resume, ModeGuided::resume in
     * ArduCopter/mode_auto.cpp and mode_guided.cpp); a vehicle in a hold mode is switched to the
     * mission mode. A vehicle disarmed on the ground has nothing to resume ([NothingInFlight],
     * nothing sent: switching it to AUTO would leave it there). After an upload that did not
     * complete: [pod.mavlink.mission.MissionHalfWritten].
     */
    public suspend fun continueMission() {
        vehicle.mission.requireWhole("resume the mission")
        if (!vehicle.telemetry.armed.value) throw NothingInFlight(vehicle.systemId, "resume")
        val mission = role(ModeRole.MISSION)
        val mode = vehicle.telemetry.mode.value?.name
        val (autopilot, type) = airframe()
        val pausedInMode = mode == mission || (autopilot == Autopilot.ARDUPILOT && type.isMultirotor && mode == role(ModeRole.GUIDED))
        if (pausedByCommand == true || (pausedByCommand == null && pausedInMode)) {
            command(VehicleCommand(DO_PAUSE_CONTINUE, param1 = 1f))
        } else {
            setMode(mission)
        }
        pausedByCommand = null
    }

    /**
     * Starts the uploaded mission (MISSION_START) at item [first], or where it stands when null,
     * and waits for the mission mode. The vehicle must be armed (PX4 arms itself), else
     * [VehicleDisarmed] before anything is sent; an ArduPilot copter's mission must begin with a
     * takeoff. [first] must be one of the vehicle's items ([NoSuchMissionItem]: the count is
     * downloaded first). ArduPilot refuses a start item in the command itself, so there the
     * current item is set first. With [arm], a disarmed vehicle is armed ([arm]) once the mission
     * on board is known to hold [first] (or any item to fly), never before, out of a mode it will not
     * arm in ([armForFlight]). After an upload that did not complete: [pod.mavlink.mission.MissionHalfWritten].
     */
    public suspend fun startMission(first: Int? = null, arm: Boolean = false) {
        require(first == null || first >= 0) { "first must be ≥ 0, was $first" }
        vehicle.mission.requireWhole("start the mission")
        val px4 = airframe().first == Autopilot.PX4
        // ArduCopter and ArduPlane take MISSION_START disarmed and switch to AUTO on the ground
        // (GCS_MAVLINK_Copter::handle_MAV_CMD_MISSION_START, ArduPlane's GCS_MAVLINK_Plane: set_mode
        // AUTO only), where the copter then refuses to arm ("Mode not armable"); PX4 arms itself
        // (Commander: VEHICLE_CMD_MISSION_START changes to AUTO_MISSION and calls arm()).
        if (!px4 && !arm) requireArmed("start the mission")
        if (first != null || arm) {
            // ArduPilot ignores MISSION_SET_CURRENT beyond its mission without a word
            // (GCS_MAVLINK::handle_mission_set_current answers only when set_current_cmd succeeds),
            // PX4 denies MISSION_START beyond seq_total: check against what the vehicle holds.
            val count = vehicle.mission.download().size
            // ArduPilot's item 0 is home: a mission to fly has more (ModeAuto::init: num_commands() > 1).
            val empty = count <= (if (px4) 0 else 1)
            if (first != null && first >= count) throw NoSuchMissionItem(vehicle.systemId, if (count == 0) null else first, count)
            if (empty) throw NoSuchMissionItem(vehicle.systemId, null, count)
        }
        if (arm) armForFlight()
        if (first != null && !px4) vehicle.mission.setCurrent(first)
        command(VehicleCommand(MISSION_START, param1 = if (px4 && first != null) first.toFloat() else 0f))
        confirmMode("start mission", ModeRole.MISSION)
    }

    /** Sets the [kind] speed (DO_CHANGE_SPEED) for the current flight and mission. */
    public suspend fun setSpeed(speed: Speed, kind: SpeedKind = SpeedKind.GROUND) {
        require(speed.metersPerSecond > 0 && speed.metersPerSecond <= 100) { "speed must be in (0, 100] m/s, was $speed" }
        command(VehicleCommand(DO_CHANGE_SPEED, param1 = SpeedTypes.of(kind).toFloat(), param2 = speed.metersPerSecond.toFloat(), param3 = -1f))
    }

    /** Sets home to [location] (altitude above sea level), or to where the vehicle is when null. */
    public suspend fun setHome(location: Location? = null) {
        command(
            if (location == null) {
                VehicleCommand(DO_SET_HOME, param1 = 1f)
            } else {
                VehicleCommand(DO_SET_HOME, param5 = location.latitude, param6 = location.longitude, param7 = location.altitude.meters.toFloat(), frame = MavFrames.GLOBAL_INT)
            },
        )
    }

    /** Asks the vehicle to send message [messageId] every [interval]; null stops it. */
    public suspend fun setMessageInterval(messageId: Int, interval: Duration?) {
        require(messageId in 0..0xFFFFFF) { "messageId must be in 0..16777215, was $messageId" }
        require(interval == null || interval.isPositive()) { "interval must be > 0, was $interval" }
        val micros = interval?.inWholeMicroseconds?.toFloat() ?: -1f
        command(VehicleCommand(SET_MESSAGE_INTERVAL, param1 = messageId.toFloat(), param2 = micros))
    }

    /**
     * Waits until the vehicle is on the ground ([isOnGround]: its landed state, or while that is
     * unknown its height) and disarmed.
     */
    public suspend fun awaitLanded(timeout: Duration = 5.minutes) {
        val t = vehicle.telemetry
        confirm("landing", "on the ground and disarmed", combine(t.landedState, t.armed, t.position) { l, a, p -> Triple(l, a, p?.relativeAltitude) }, timeout, describe = { "${it.first.name.lowercase()}, ${if (it.second) "armed" else "disarmed"}" }) {
            isOnGround(it.first, it.third) && !it.second
        }
    }

    /** Waits until the vehicle is within [within] of [target] horizontally and vertically. */
    public suspend fun awaitArrival(target: Location, within: Distance = 2.m, timeout: Duration = 5.minutes) {
        confirm("arrival at $target", "within $within", vehicle.telemetry.position, timeout) { p ->
            p != null && p.location.copy(altitude = target.altitude).distanceTo(target).meters <= within.meters &&
                kotlin.math.abs(p.location.altitude.meters - target.altitude.meters) <= within.meters
        }
    }

    private suspend fun command(command: VehicleCommand) {
        vehicle.commands.send(command)
    }

    private fun airframe(): Pair<Autopilot, VehicleType> = vehicle.identity.value.let { it.autopilot to it.type }

    private fun isPlane(type: VehicleType) = type == VehicleType.FIXED_WING || type == VehicleType.VTOL

    private fun role(role: ModeRole): String {
        val (autopilot, type) = airframe()
        return FlightModes.forRole(autopilot, type, role)
            ?: throw ActionUnsupported(role.name.lowercase(), "$autopilot ${type.name.lowercase()} has no mode for it")
    }

    /** Whether the vehicle shows, within a few telemetry reports, that it has left the ground. */
    private suspend fun leavingGround(): Boolean = withTimeoutOrNull(3.seconds) {
        combine(vehicle.telemetry.landedState, vehicle.telemetry.position) { landed, position ->
            isAirborne(landed, position?.relativeAltitude)
        }.first { it }
    } ?: false

    /**
     * Home's altitude above sea level, waiting up to [confirmTimeout] for HOME_POSITION or a
     * GLOBAL_POSITION_INT to tell it: a command run as soon as a vehicle is heard comes before them.
     */
    private suspend fun awaitHomeAltitude(): Double = homeAltitude() ?: withTimeoutOrNull(confirmTimeout) {
        combine(vehicle.telemetry.home, vehicle.telemetry.position) { _, _ -> homeAltitude() }.first { it != null }
    } ?: throw VehicleNotReady(vehicle.systemId, "its home altitude (no HOME_POSITION or GLOBAL_POSITION_INT heard)", confirmTimeout, "take off")

    private fun homeAltitude(): Double? =
        vehicle.telemetry.home.value?.altitude?.meters
            ?: vehicle.telemetry.position.value?.let { it.location.altitude.meters - it.relativeAltitude.meters }

    private suspend fun confirmMode(action: String, role: ModeRole) {
        val name = role(role)
        confirm(action, "mode $name", vehicle.telemetry.mode) { it?.name == name }
    }

    /**
     * Waits for [ok] on [state]; fails on timeout with the last value seen (in words, by
     * [describe]), when the vehicle is lost, or, with [untilDisarmed], as soon as it disarms.
     */
    private suspend fun <T> confirm(
        action: String,
        expected: String,
        state: kotlinx.coroutines.flow.Flow<T>,
        timeout: Duration = confirmTimeout,
        untilDisarmed: Boolean = false,
        describe: (T) -> String = ::stateText,
        ok: (T) -> Boolean,
    ) {
        var last: T? = null
        var seen = false
        val outcome = withTimeoutOrNull(timeout) {
            combine(state, vehicle.connection, vehicle.telemetry.armed) { value, connection, armed -> Triple(value, connection, armed) }
                .first { (value, connection, armed) ->
                    last = value
                    seen = true
                    ok(value) || connection == ConnectionState.LOST || (untilDisarmed && !armed)
                }
        } ?: run {
            // The state can turn right at the deadline, after the check saw it but before `first`
            // returned: what was seen last decides, not the race.
            @Suppress("UNCHECKED_CAST")
            if (seen && ok(last as T)) return
            throw ActionNotConfirmed(action, expected, if (seen) describe(last as T) else "nothing", timeout)
        }
        if (ok(outcome.first)) return
        if (outcome.second == ConnectionState.LOST) throw VehicleLost(vehicle.systemId, action)
        throw DisarmedDuring(vehicle.systemId, action, describe(outcome.first))
    }

    private fun requireArmed(action: String) {
        if (!vehicle.telemetry.armed.value) throw VehicleDisarmed(vehicle.systemId, action)
    }

    private companion object {
        /** Between arm attempts while the vehicle initialises: ArduPilot runs its pre-arm checks at 1 Hz. */
        val ARM_RETRY = 1.seconds
        const val GPS_FIX_3D = 3
        const val MAV_STATE_UNINIT = 0
        const val MAV_STATE_BOOT = 1
        const val MAV_STATE_CALIBRATING = 2
    }
}
