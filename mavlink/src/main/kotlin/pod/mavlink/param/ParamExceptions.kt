package pod.mavlink.param

import pod.core.units.toReadable
import kotlin.time.Duration

/** A parameter could not be read or written. */
public sealed class ParamException(message: String) : pod.core.PodException(message) {
    /** The parameter's name. */
    public abstract val name: String
}

/**
 * No PARAM_VALUE for [name] came back within [waited] after [attempts] requests: the vehicle has
 * no such parameter (ArduPilot and PX4 both stay silent then) or the link is down.
 */
public class ParamTimeout(
    override val name: String,
    /** How many requests were sent. */
    public val attempts: Int,
    /** How long Pod waited. */
    public val waited: Duration,
) : ParamException("no PARAM_VALUE for $name after $attempts requests over ${waited.toReadable()}: the vehicle may have no such parameter")

/** The vehicle kept [actual] instead of [requested] for [name] (read-only, out of range, or refused). */
public class ParamRejected(
    override val name: String,
    /** The value Pod asked for. */
    public val requested: Double,
    /** The value the vehicle reports. */
    public val actual: Double,
) : ParamException("the vehicle kept $name = ${number(actual)} instead of ${number(requested)} (read-only, out of its range, or refused)")

/**
 * [value] does not fit parameter [name] of [type], which holds only [range]: nothing was sent.
 * PARAM_VALUE carries no range; the type's own is the one a ground station always knows
 * (ArduPilot publishes the documented ranges only in its build's apm.pdef.xml, PX4 in the
 * parameters.json of its COMPONENT_METADATA, fetched over MAVLink FTP).
 */
public class ParamOutOfRange(
    override val name: String,
    /** How the vehicle stores the parameter. */
    public val type: ParamType,
    /** The value asked for. */
    public val value: Double,
    /** What the type holds. */
    public val range: ClosedFloatingPointRange<Double>,
) : ParamException("$name is an integer parameter (${type.name}) holding ${number(range.start)}..${number(range.endInclusive)}: ${number(value)} does not fit")

/** [v] as people write it: whole numbers without ".0". */
internal fun number(v: Double): String = if (v == kotlin.math.floor(v) && kotlin.math.abs(v) < 1e15) v.toLong().toString() else v.toString()
