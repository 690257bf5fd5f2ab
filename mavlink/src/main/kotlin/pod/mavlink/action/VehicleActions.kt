package pod.mavlink.action

import kotlinx.coroutines.flow.StateFlow
import pod.core.mission.SpeedKind
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.Speed
import pod.core.units.m
import pod.core.vehicle.isOnGround
import pod.core.vehicle.VehicleLost
import pod.mavlink.MavFrames
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.MavCommands.DO_CHANGE_SPEED
import pod.mavlink.command.MavCommands.DO_SET_HOME
import pod.mavlink.command.MavCommands.SET_MESSAGE_INTERVAL
import pod.mavlink.command.SpeedTypes
import pod.mavlink.command.VehicleCommand
import pod.mavlink.telemetry.FlightModes
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes

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
 *
 * Each concern lives in its own part: [Arming], [ModeSwitch], [TakeoffAndLanding],
 * [GuidedFlight], [MissionActions], [GettingAirborne]; they share the confirmation waits
 * ([StateWaits]) and the wait for a vehicle still initialising ([Readiness]).
 */
public class VehicleActions internal constructor(
    private val vehicle: MavlinkVehicle,
    /** How long confirmations and readiness waits last ([pod.mavlink.VehicleTiming.actions]). */
    public val timing: ActionTiming,
) {
    private val waits = StateWaits(vehicle, timing.confirmTimeout)
    private val readiness = Readiness(vehicle, timing.readyTimeout)
    private val modes = ModeSwitch(vehicle, readiness, waits)
    private val arming = Arming(vehicle, readiness, waits)
    private val flight = TakeoffAndLanding(vehicle, modes, waits, timing.confirmTimeout)
    private val guided = GuidedFlight(vehicle, modes, waits)
    private val missions = MissionActions(vehicle, this, modes, guided, waits)

    /**
     * What [arm] is waiting for now, in the autopilot's words ("Arm: AHRS: waiting for home"), or
     * null when it is not waiting: for a UI or a log to show while a vehicle initialises.
     */
    public val waitingFor: StateFlow<String?> = readiness.waitingFor

    /**
     * Arms the motors ([force] skips the autopilot's pre-arm checks) and waits until telemetry shows
     * it armed. A vehicle still initialising (its refusal names the estimator, home, GPS or settling
     * sensors) is asked again every second for up to [ActionTiming.readyTimeout], with [waitingFor] saying
     * why; then [VehicleNotReady]. A refusal waiting cannot clear (battery, mode) fails at once with
     * the autopilot's reason ([pod.mavlink.command.CommandRejected]).
     */
    public suspend fun arm(force: Boolean = false): Unit = arming.arm(force)

    /** Disarms the motors ([force] even in flight, which drops a multicopter) and waits until telemetry shows it. */
    public suspend fun disarm(force: Boolean = false): Unit = arming.disarm(force)

    /**
     * Switches to the mode called [name] ("GUIDED", "AUTO", "AUTO.MISSION" on PX4, …) and waits
     * until the heartbeat reports it. Throws [UnknownMode] for a name the vehicle does not have. A
     * refusal that clears once the estimator has a position (ArduCopter's "Mode change to GUIDED
     * failed: requires position" after boot) is waited out like [arm]'s, with [waitingFor] saying
     * why, for up to [ActionTiming.readyTimeout]; then [VehicleNotReady].
     */
    public suspend fun setMode(name: String): Unit = modes.setMode(name)

    /**
     * Takes off to [altitude] above home and waits until it is reached (within 5 %, at least
     * 1 m) or [timeout] passes. The vehicle must be armed ([VehicleDisarmed] otherwise, before
     * anything changes) and stay so ([DisarmedDuring] as soon as it disarms). ArduPilot copters switch to GUIDED
     * first; ArduPilot planes use TAKEOFF mode with TKOFF_ALT; PX4 takes NAV_TAKEOFF to an
     * altitude above sea level, computed from home.
     */
    public suspend fun takeoff(altitude: Distance, timeout: Duration = 2.minutes) {
        require(altitude.meters > 0 && altitude.meters <= 10_000) { "altitude must be in (0, 10000] m, was $altitude" }
        flight.takeoff(altitude, timeout)
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
    public suspend fun land(): Unit = flight.land()

    /** Returns to launch (NAV_RETURN_TO_LAUNCH), confirmed by the return mode. */
    public suspend fun returnToLaunch(): Unit = flight.returnToLaunch()

    /**
     * Flies to [target] (altitude above sea level) and holds there, at [speed] or the vehicle's
     * own: DO_REPOSITION as COMMAND_INT (ArduPilot takes it only in that form), switching to the
     * guided mode first. Returns once accepted; [awaitArrival] waits until it is there.
     */
    public suspend fun goto(target: Location, speed: Speed? = null): Unit = guided.goto(target, speed)

    /**
     * Stops and holds position and altitude without needing anyone on the sticks, and waits until
     * the heartbeat shows the mode: BRAKE on an ArduCopter, AUTO.LOITER on PX4; a plane circles
     * where it is (ArduPlane LOITER). See [FlightModes.forRole] for the autopilots' sources.
     */
    public suspend fun hold(): Unit = guided.hold()

    /**
     * Pauses the mission where the vehicle is, holding position and altitude: with
     * DO_PAUSE_CONTINUE where the autopilot supports it (ArduCopter), by switching to the hold
     * mode otherwise. [continueMission] resumes at the same item either way. A vehicle disarmed on
     * the ground has nothing to pause ([NothingInFlight], nothing sent).
     */
    public suspend fun pauseMission(): Unit = missions.pause()

    /**
     * Resumes what [pauseMission] paused, by this process or another: a mission at the item it was
     * on, or an ArduCopter's goto in GUIDED, which flies on to its destination. An ArduCopter in
     * AUTO or GUIDED is resumed with DO_PAUSE_CONTINUE (ModeAuto::resume, ModeGuided::resume in
     * ArduCopter/mode_auto.cpp and mode_guided.cpp); a vehicle in a hold mode is switched to the
     * mission mode. A vehicle disarmed on the ground has nothing to resume ([NothingInFlight],
     * nothing sent: switching it to AUTO would leave it there). After an upload that did not
     * complete: [pod.mavlink.mission.MissionHalfWritten].
     */
    public suspend fun continueMission(): Unit = missions.resume()

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
        missions.start(first, arm)
    }

    /** Sets the [kind] speed (DO_CHANGE_SPEED) for the current flight and mission. */
    public suspend fun setSpeed(speed: Speed, kind: SpeedKind = SpeedKind.GROUND) {
        require(speed.metersPerSecond > 0 && speed.metersPerSecond <= 100) { "speed must be in (0, 100] m/s, was $speed" }
        vehicle.commands.send(VehicleCommand(DO_CHANGE_SPEED, param1 = SpeedTypes.of(kind).toFloat(), param2 = speed.metersPerSecond.toFloat(), param3 = -1f))
    }

    /** Sets home to [location] (altitude above sea level), or to where the vehicle is when null. */
    public suspend fun setHome(location: Location? = null) {
        vehicle.commands.send(
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
        vehicle.commands.send(VehicleCommand(SET_MESSAGE_INTERVAL, param1 = messageId.toFloat(), param2 = micros))
    }

    /**
     * Waits until the vehicle is on the ground ([isOnGround]: its landed state, or while that is
     * unknown its height) and disarmed.
     */
    public suspend fun awaitLanded(timeout: Duration = 5.minutes): Unit = flight.awaitLanded(timeout)

    /** Waits until the vehicle is within [within] of [target] horizontally and vertically. */
    public suspend fun awaitArrival(target: Location, within: Distance = 2.m, timeout: Duration = 5.minutes): Unit =
        guided.awaitArrival(target, within, timeout)
}
