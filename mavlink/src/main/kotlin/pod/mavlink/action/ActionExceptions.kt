package pod.mavlink.action

import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.core.units.toReadable
import kotlin.time.Duration

/** An action the vehicle did not confirm. Command failures come as [pod.mavlink.command.CommandException]. */
public sealed class ActionException(message: String) : pod.core.PodException(message)

/** [mode] is not a mode of [autopilot] flying [type]; [known] lists the ones that are. */
public class UnknownMode(
    /** The name asked for. */
    public val mode: String,
    /** The vehicle's autopilot. */
    public val autopilot: Autopilot,
    /** The vehicle's airframe. */
    public val type: VehicleType,
    /** Mode names the vehicle has. */
    public val known: List<String>,
) : ActionException("$autopilot ${type.name.lowercase()} has no mode \"$mode\"; known: ${known.joinToString()}")

/** The vehicle has no way to do [action] (an ArduPilot plane cannot land without a landing sequence). */
public class ActionUnsupported(
    /** What was asked. */
    public val action: String,
    /** Why it cannot be done. */
    public val reason: String,
) : ActionException("$action: $reason")

/**
 * The vehicle accepted [action] but its telemetry did not show [expected] within [waited];
 * [observed] is what it showed last.
 */
public class ActionNotConfirmed(
    /** What was asked. */
    public val action: String,
    /** The state that would have confirmed it. */
    public val expected: String,
    /** The state seen last. */
    public val observed: String,
    /** How long Pod watched. */
    public val waited: Duration,
) : ActionException("$action was accepted but the vehicle did not show $expected within ${waited.toReadable()} (last seen: $observed)")

/**
 * The vehicle was still initialising when [waited] ran out: it kept refusing to [action] ("arm",
 * "switch to GUIDED") with [reason] (the autopilot's own words), a refusal that clears by waiting
 * after boot.
 */
public class VehicleNotReady(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** What it was waiting for, in the autopilot's words. */
    public val reason: String,
    /** How long Pod waited. */
    public val waited: Duration,
    /** What it kept refusing. */
    public val action: String = "arm",
) : ActionException("vehicle $systemId was still not ready to $action after ${waited.toReadable()}: $reason")

/** [action] needs the motors armed and vehicle [systemId] reports them disarmed; nothing was sent. */
public class VehicleDisarmed(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** What was asked ("take off", "start the mission"). */
    public val action: String,
) : ActionException("vehicle $systemId is disarmed: arm it first to $action")

/**
 * Vehicle [systemId] disarmed itself while Pod waited for [action] to show (PX4 disarms a vehicle
 * left on the ground for COM_DISARM_PRFLT seconds); [observed] is what it showed last.
 */
public class DisarmedDuring(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** What was under way. */
    public val action: String,
    /** The state seen last, in words. */
    public val observed: String,
) : ActionException("vehicle $systemId disarmed itself during $action ($observed)")

/**
 * Vehicle [systemId] holds [count] mission items and there is no item [item] to start from
 * (an empty mission has none at all).
 */
public class NoSuchMissionItem(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** The item asked for, or null for "where it stands". */
    public val item: Int?,
    /** How many items the vehicle reports (MISSION_COUNT; on ArduPilot item 0 is home). */
    public val count: Int,
) : ActionException(
    if (item == null) {
        "vehicle $systemId holds no mission: upload one first"
    } else {
        "vehicle $systemId holds $count mission items (0..${count - 1}): there is no item $item to start from"
    },
)

/**
 * Vehicle [systemId] is disarmed on the ground, so there is nothing under way to [action]
 * ("pause", "resume"); nothing was sent.
 */
public class NothingInFlight(
    /** The vehicle's system id. */
    public val systemId: Int,
    /** What was asked. */
    public val action: String,
) : ActionException("vehicle $systemId is disarmed on the ground: there is no mission or goto in flight to $action")
