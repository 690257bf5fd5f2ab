package pod.mavlink.param

import kotlin.time.Duration

/** A parameter could not be read or written. */
public sealed class ParamException(message: String) : Exception(message) {
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
) : ParamException("no PARAM_VALUE for $name after $attempts requests over $waited: the vehicle may have no such parameter")

/** The vehicle kept [actual] instead of [requested] for [name] (read-only, out of range, or refused). */
public class ParamRejected(
    override val name: String,
    /** The value Pod asked for. */
    public val requested: Double,
    /** The value the vehicle reports. */
    public val actual: Double,
) : ParamException("the vehicle kept $name = $actual instead of $requested")
