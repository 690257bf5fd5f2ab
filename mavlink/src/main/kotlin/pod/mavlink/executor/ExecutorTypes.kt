package pod.mavlink.executor

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** Where a [MissionExecutor] is in its run. */
public enum class MissionRunState {
    /** Not started. */
    IDLE,

    /** Clearing the vehicle's list and uploading the mission. */
    UPLOADING,

    /** Arming and starting the vehicle. */
    STARTING,

    /** The vehicle flies the mission. */
    FLYING,

    /** The vehicle circles the unlimited loiter that ends the mission, until the run is cancelled. */
    LOITERING,

    /** The mission is complete. */
    COMPLETED,

    /** The run failed with an exception. */
    FAILED,

    /** The run was cancelled; the vehicle was left as it was. */
    CANCELLED,
}

/** How far a vehicle is through a mission. */
public data class MissionProgress(
    /** The step the vehicle is on, or null before the first and after the last. */
    public val step: Int?,
    /** How many steps are done. */
    public val stepsDone: Int,
    /** How many steps the mission has. */
    public val stepCount: Int,
    /** The mission item the vehicle reports as current, or null before the start. */
    public val item: Int?,
)

/** Time limits of a [MissionExecutor] (flight itself has none: a lost vehicle fails it instead). */
public data class ExecutorTiming(
    /** How long to wait for the vehicle's home when the mission names none. */
    public val homeTimeout: Duration = 10.seconds,
    /** How long the vehicle may be out of its mission mode before the run fails with [MissionInterrupted]. */
    public val modeGrace: Duration = 3.seconds,
) {
    init {
        require(homeTimeout.isPositive()) { "homeTimeout must be > 0, was $homeTimeout" }
        require(modeGrace.isPositive()) { "modeGrace must be > 0, was $modeGrace" }
    }
}

/** A mission a vehicle could not fly to its end. */
public sealed class MissionExecutionException(message: String) : pod.core.PodException(message) {
    /** The mission's name. */
    public abstract val mission: String
}

/** The mission cannot be flown by this vehicle as it is ([reason] says why); nothing was sent. */
public class MissionNotFlyable(
    override val mission: String,
    /** Why not. */
    public val reason: String,
) : MissionExecutionException("mission \"$mission\" cannot be flown: $reason")

/**
 * The vehicle left its mission mode for [mode] (a pilot, a failsafe, another ground station) at
 * [step] and did not come back within the grace time; [said] is what it reported around the switch
 * (a failsafe's reason: "Polygon fence breached", "Failsafe activated"). The engine leaves the
 * vehicle in the mode it chose ([pod.core.platform.AutopilotTookControl]).
 */
public class MissionInterrupted(
    override val mission: String,
    /** The mode it switched to. */
    public val mode: String,
    /** The step it was on (an index into the mission's steps; the message counts from 1), or null. */
    public val step: Int?,
    /** The vehicle's notices, warnings and errors (STATUSTEXT) from shortly before the switch until the grace time ran out, oldest first. */
    public val said: List<String> = emptyList(),
) : MissionExecutionException(
    "mission \"$mission\" interrupted: the vehicle switched to $mode" + (step?.let { " at step ${it + 1}" } ?: "") +
        (if (said.isEmpty()) "" else "; it said: " + said.joinToString("; ") { "\"$it\"" }),
),
    pod.core.platform.AutopilotTookControl

/**
 * The vehicle disarmed on the ground before the mission was complete, at [step] (an index into
 * the mission's steps; the message counts from 1): it crashed, touched down short of its landing,
 * or someone disarmed it. [said] is what it reported shortly before (a crash, a failsafe).
 */
public class MissionDisarmed(
    override val mission: String,
    /** The step it was on, or null. */
    public val step: Int?,
    /** The vehicle's notices, warnings and errors (STATUSTEXT) from shortly before it disarmed, oldest first. */
    public val said: List<String> = emptyList(),
) : MissionExecutionException(
    "mission \"$mission\" ended early: the vehicle disarmed on the ground" + (step?.let { " at step ${it + 1}" } ?: "") +
        (if (said.isEmpty()) "" else "; it said: " + said.joinToString("; ") { "\"$it\"" }),
)
