package pod.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.convert
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.double
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.distinctUntilChanged
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import pod.cli.json.Event
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.MavlinkVehicle
import pod.mavlink.action.NothingInFlight
import pod.mavlink.action.VehicleDisarmed
import kotlin.time.Duration.Companion.seconds

/**
 * A one-step vehicle action: does it, waits for the vehicle's confirmation, and ends with a
 * `done` line naming the action and the vehicle's mode and armed state. Interrupted, it leaves an
 * armed vehicle holding where it is ([MavlinkVehicle.action]`.hold()`: a mode that keeps its
 * height with nobody on the sticks); actions that are themselves the safe end of a flight (land,
 * return, disarm, pause) leave the vehicle doing them.
 */
internal abstract class ActionCommand(out: Output, name: String, private val summary: String) : VehicleCommandBase(out, name) {
    override fun help(context: Context): String = summary

    /** Performs the action; returns what to print for people. */
    protected abstract suspend fun perform(vehicle: MavlinkVehicle): String

    /** Whether an interrupted action leaves the vehicle as it is instead of holding. */
    protected open val safeAsItIs: Boolean = false

    override suspend fun afterInterrupt(vehicle: MavlinkVehicle): String {
        val t = vehicle.telemetry
        if (safeAsItIs) return "left ${t.mode.value?.name ?: "as it was"}"
        return holdIfArmed(vehicle)
    }

    /** What to add when the action needs the vehicle armed and it is not: another way than `pod arm`, if the command has one. */
    protected open val armHint: String = ""

    /** What to do instead when the vehicle is on the ground with nothing in flight to act on. */
    protected open val groundHint: String = ""

    override suspend fun act(vehicle: MavlinkVehicle) {
        val text = try {
            perform(vehicle)
        } catch (e: VehicleDisarmed) {
            fail("vehicle ${e.systemId} is disarmed: arm it first with `pod arm`$armHint")
        } catch (e: NothingInFlight) {
            fail("${e.message}$groundHint")
        }
        finish("vehicle ${vehicle.systemId}: $text", vehicle, action = commandName)
    }
}

internal class ArmCommand(out: Output) : ActionCommand(out, "arm", "Arm the motors and wait until the vehicle reports it armed.") {
    private val force by option("--force", help = "skip the autopilot's pre-arm checks").flag()

    // A vehicle still initialising is waited for: say what it waits for, each new reason once.
    override suspend fun perform(vehicle: MavlinkVehicle): String = coroutineScope {
        val progress = launch {
            vehicle.action.waitingFor.filterNotNull().distinctUntilChanged().collect { reason ->
                if (json) emit(Event.Waiting(vehicle.systemId, reason)) else out.line("vehicle ${vehicle.systemId}: waiting: $reason")
            }
        }
        try {
            vehicle.action.arm(force)
            "armed"
        } finally {
            progress.cancel()
        }
    }
}

internal class DisarmCommand(out: Output) : ActionCommand(out, "disarm", "Disarm the motors and wait until the vehicle reports it disarmed.") {
    private val force by option("--force", help = "even in flight (a multicopter falls)").flag()
    override val safeAsItIs: Boolean = true
    override suspend fun perform(vehicle: MavlinkVehicle) = vehicle.action.disarm(force).let { "disarmed" }
}

internal class ModeCommand(out: Output) : ActionCommand(out, "mode", "Switch flight mode (GUIDED, AUTO, LOITER, RTL…; AUTO.MISSION etc. on PX4).") {
    private val name by argument(help = "mode name")
    override suspend fun perform(vehicle: MavlinkVehicle) = vehicle.action.setMode(name).let { "mode ${name.uppercase()}" }
}

internal class TakeoffCommand(out: Output) : ActionCommand(
    out, "takeoff",
    "Take off to ALT metres above home and wait until it is reached, from whatever state the vehicle is in: it is switched to its take-off mode and armed first when needed, and the line says so.",
) {
    init {
        // `pod takeoff -5` is a wrong altitude, said once, not an unknown option plus a missing ALT.
        negativeNumbersAsArguments()
    }

    private val altitude by argument("ALT", help = "metres above home, above 0 and at most 10000").convert {
        val a = it.toDoubleOrNull() ?: fail("not a number of metres: '$it'")
        if (!(a > 0 && a <= 10_000)) fail("the altitude must be above 0 m and at most 10000 m, was $it")
        a
    }
    override suspend fun perform(vehicle: MavlinkVehicle): String {
        val changed = vehicle.action.getAirborne(altitude.m)
        val before = changed.dropLast(1) // the last is the take-off itself
        return when {
            changed.isEmpty() -> "already flying; nothing changed"
            before.isEmpty() -> "at $altitude m"
            else -> "at $altitude m (${before.joinToString(", ")})"
        }
    }
}

internal class LandCommand(out: Output) : ActionCommand(out, "land", "Land (an ArduPlane through its mission's landing sequence, or, with none on board, at home after a planned approach that replaces its mission).") {
    override val safeAsItIs: Boolean = true
    private val untilLanded by option("--until-landed", help = "wait for touchdown and disarm").flag()
    override suspend fun perform(vehicle: MavlinkVehicle): String {
        vehicle.action.land()
        if (!untilLanded) return "landing"
        vehicle.action.awaitLanded()
        return "landed"
    }
}

internal class RtlCommand(out: Output) : ActionCommand(out, "rtl", "Return to launch.") {
    override val safeAsItIs: Boolean = true
    private val untilLanded by option("--until-landed", help = "wait for touchdown and disarm (multicopters)").flag()
    override suspend fun perform(vehicle: MavlinkVehicle): String {
        vehicle.action.returnToLaunch()
        if (!untilLanded) return "returning"
        vehicle.action.awaitLanded()
        return "landed at home"
    }
}

internal class GotoCommand(out: Output) : ActionCommand(out, "goto", "Fly to LAT LON at ALT metres above home and hold there.") {
    init {
        // A western longitude or southern latitude ("-8.59") is a number here, not an unknown option.
        negativeNumbersAsArguments()
    }

    private val lat by argument("LAT").double().restrictTo(-90.0..90.0)
    private val lon by argument("LON").double().restrictTo(-180.0..180.0)
    private val alt by argument("ALT", help = "metres above home").double().restrictTo(0.0..10_000.0)
    private val amsl by option("--amsl", help = "ALT is above mean sea level, not above home").flag()
    private val arrive by option("--arrive", help = "wait until the vehicle is there").flag()
    override val armHint: String = ", then take off with `pod takeoff ALT`"

    override suspend fun perform(vehicle: MavlinkVehicle): String {
        val base = if (amsl) 0.0 else homeAltitude(vehicle)
        val target = Location(lat, lon, (base + alt).m)
        vehicle.action.goto(target)
        if (!arrive) return "going to $lat, $lon"
        vehicle.action.awaitArrival(target, within = 5.m)
        return "at $lat, $lon"
    }

    private suspend fun homeAltitude(vehicle: MavlinkVehicle): Double {
        val t = vehicle.telemetry
        val position = withTimeoutOrNull(5.seconds) { t.position.first { it != null } }
        return t.home.value?.altitude?.meters
            ?: position?.let { it.location.altitude.meters - it.relativeAltitude.meters }
            ?: fail("no position from vehicle ${vehicle.systemId} to tell its home altitude; pass --amsl")
    }
}

internal class PauseCommand(out: Output) : ActionCommand(out, "pause", "Pause the mission, holding position and altitude.") {
    override val safeAsItIs: Boolean = true
    override val groundHint: String = "; start a mission with `pod start --arm`"
    override suspend fun perform(vehicle: MavlinkVehicle) = vehicle.action.pauseMission().let { "paused" }
}

internal class ResumeCommand(out: Output) : ActionCommand(
    out, "resume",
    "Continue what `pod pause` paused: a mission at the item it was on, or an ArduCopter's goto (refused on the ground).",
) {
    override val groundHint: String = "; start the mission with `pod start --arm`"
    override suspend fun perform(vehicle: MavlinkVehicle) = vehicle.action.continueMission().let { "resumed" }
}

internal class StartCommand(out: Output) : ActionCommand(out, "start", "Start the uploaded mission (arm first, or pass --arm).") {
    private val from by option("--from", help = "first item to fly (checked against the mission on board)").int().restrictTo(0..65535)
    private val arm by option("--arm", help = "arm the vehicle first").flag()
    override val armHint: String = ", or pass --arm"

    override suspend fun perform(vehicle: MavlinkVehicle): String {
        // The mission on board is checked before the motors are armed.
        vehicle.action.startMission(from, arm = arm)
        return "mission started" + (from?.let { " at item $it" } ?: "")
    }
}

/** Every action command, in the order `pod --help` lists them. */
internal fun actionCommands(out: Output) = listOf(
    ArmCommand(out), DisarmCommand(out), ModeCommand(out), TakeoffCommand(out), LandCommand(out), RtlCommand(out),
    GotoCommand(out), PauseCommand(out), ResumeCommand(out), StartCommand(out),
)
