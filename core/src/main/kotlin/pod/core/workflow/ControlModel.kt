package pod.core.workflow

/** Which part of a survey workflow is flown: the photo pass, the revisit of flagged waypoints, or the way home. */
public enum class Pass {
    /** Every waypoint, in order (photos, detections). */
    FORWARD,

    /** Only the flagged waypoints (e.g. a range measurement at each). */
    BACKWARD,

    /** Both passes done: flying home (a multirotor lands there). */
    HOME,
}

/** The states an operator sees. */
public sealed interface ControlPhase {
    /** No vehicle ready yet (not heard, initialising, or not armable). */
    public data object Waiting : ControlPhase

    /** A vehicle is ready; no path built. */
    public data object Ready : ControlPhase

    /** A path is built and can be started, or cancelled. */
    public data object PathBuilt : ControlPhase

    /**
     * Flying [pass], at [waypoint] once known.
     *
     * @property pass the pass being flown (forward or backward).
     * @property waypoint the index into the pass's waypoints of the one flown to, or null until the vehicle reports it.
     */
    public data class Executing(val pass: Pass, val waypoint: Int? = null) : ControlPhase

    /**
     * Paused in [pass] at [waypoint]: holding position and altitude.
     *
     * @property pass the pass that was being flown.
     * @property waypoint the index into the pass's waypoints it paused at, or null when it was not known yet.
     */
    public data class Paused(val pass: Pass, val waypoint: Int? = null) : ControlPhase

    /** Both passes flown (or no backward pass needed); the vehicle landed at home. */
    public data object Finished : ControlPhase

    /**
     * Aborted by the operator or by a failure: the vehicle holds, then returns home.
     *
     * @property reason why, in words, for the operator.
     */
    public data class Aborted(val reason: String) : ControlPhase
}

/** What the app shows: the [phase], the [plan] built (if any), and the event id it reflects. */
public data class ControlState<P>(
    /** The state the operator sees. */
    val phase: ControlPhase,
    /** The path built, or null. */
    val plan: P?,
    /** The id of the latest command this state reflects (0: none yet). */
    val eventId: Long,
)

/** An operator's command, with its event id (growing with each command). */
public sealed interface ControlCommand<out P> {
    /** Grows with every command the operator sends. */
    public val eventId: Long

    /**
     * Build a path: [plan] (a survey of an operator's polygon).
     *
     * @property plan the path to fly once started.
     */
    public data class Build<P>(override val eventId: Long, val plan: P) : ControlCommand<P>

    /** Drop the built path. */
    public data class CancelPath(override val eventId: Long) : ControlCommand<Nothing>

    /** Fly the built path. */
    public data class Start(override val eventId: Long) : ControlCommand<Nothing>

    /** Hold where the vehicle is, at its altitude. */
    public data class Pause(override val eventId: Long) : ControlCommand<Nothing>

    /** Go on from where it paused. */
    public data class Resume(override val eventId: Long) : ControlCommand<Nothing>

    /** Stop: hold, then return home (never descend in place). */
    public data class Abort(override val eventId: Long) : ControlCommand<Nothing>
}

/**
 * What the flight says about itself, stamped with the event id of the latest command it had
 * applied when it said it ([eventId]).
 */
public sealed interface ControlReport {
    /** The latest command the flight had applied. */
    public val eventId: Long

    /**
     * Whether a vehicle is ready to fly while nothing is built or flown.
     *
     * @property ready true when a vehicle is heard, initialised and armable.
     */
    public data class Vehicle(override val eventId: Long, val ready: Boolean) : ControlReport

    /**
     * Flying [pass] at [waypoint].
     *
     * @property pass the pass being flown.
     * @property waypoint the index into the pass's waypoints of the one flown to, or null before the vehicle reports one.
     */
    public data class Flying(override val eventId: Long, val pass: Pass, val waypoint: Int?) : ControlReport

    /**
     * Holding in [pass] at [waypoint] after a pause.
     *
     * @property pass the pass that was being flown.
     * @property waypoint the index into the pass's waypoints it holds at, or null when not known.
     */
    public data class Holding(override val eventId: Long, val pass: Pass, val waypoint: Int?) : ControlReport

    /** Done: landed at home. */
    public data class Done(override val eventId: Long) : ControlReport

    /**
     * Stopped (an abort carried out, or a failure): holding or returning home.
     *
     * @property reason why, in words, for the operator.
     */
    public data class Stopped(override val eventId: Long, val reason: String) : ControlReport
}

/** What a command did. */
public sealed interface CommandOutcome<out P> {
    /**
     * Taken: the app now shows [state].
     *
     * @property state the state right after the command.
     */
    public data class Accepted<P>(val state: ControlState<P>) : CommandOutcome<P>

    /**
     * Refused: nothing changed.
     *
     * @property reason why the command does not apply in the current phase, in words.
     */
    public data class Refused(val reason: String) : CommandOutcome<Nothing>
}

/**
 * What the operator asked for last, as the flight side reads it: the app's [state] right after the
 * latest command, and the event id of the start command of the flight that state is about
 * ([startedBy], 0 before any): a flight side that missed commands in between (it reads the latest
 * only) still knows whether this is a flight it has not flown yet.
 *
 * @property state the app's state right after the latest command.
 * @property startedBy the event id of the start command of the flight [state] is about, 0 before any start.
 */
public data class ControlIntent<P>(val state: ControlState<P>, val startedBy: Long)
