package pod.core.workflow

import pod.core.PodException
import pod.core.units.Distance
import pod.core.units.Location
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * What a waypoint action knows and can do while its vehicle holds on a waypoint: which waypoint,
 * where, and the vehicle's camera. Platforms implement it (the MAVLink one also hands out the
 * vehicle itself, for any other command or sensor).
 */
public interface WaypointVisit {
    /** The waypoint's number, from 0, in the pass being flown. */
    public val index: Int

    /** Where it is (altitude above home). */
    public val point: Location

    /** Takes one photo and returns what the vehicle reports of it, within [timeout]. */
    public suspend fun takePhoto(timeout: Duration = 10.seconds): Photo

    /** The distance the vehicle's downward rangefinder measures now, within [timeout]. */
    public suspend fun measureRange(timeout: Duration = 5.seconds): Distance
}

/** A photo the vehicle reported taking. */
public data class Photo(
    /** Its number since the vehicle booted. */
    val index: Int,
    /** Where it was taken (altitude above mean sea level). */
    val location: Location,
    /** Height above home where it was taken. */
    val relativeAltitude: Distance,
    /** Whether the capture succeeded. */
    val success: Boolean,
    /** Where the image is, or what the vehicle says of it (the simulator puts its detections here); empty when it says nothing. */
    val fileUrl: String,
)

/**
 * What a forward action says of a waypoint: whether to revisit it ([flagged]) and its [value] (a photo's detections).
 *
 * @property flagged true when the backward pass should visit this waypoint again.
 * @property value what the action found there, kept in the run's record.
 */
public data class Forward<F>(val flagged: Boolean, val value: F)

/** What a failed waypoint action leads to. */
public sealed interface OnFailure {
    /** Record no result and go on to the next waypoint. */
    public data object Skip : OnFailure

    /**
     * Run the action up to [times] more times, then abort.
     *
     * @property times how many more tries after the first failure.
     * @throws IllegalArgumentException when [times] is not in 1..100.
     */
    public data class Retry(val times: Int) : OnFailure {
        init {
            require(times in 1..100) { "times must be in 1..100, was $times" }
        }
    }

    /** End the flight with [WaypointActionFailed]. */
    public data object Abort : OnFailure
}

/**
 * One waypoint flown: when it was [reached], when the vehicle had stopped and the action [began]
 * (null: no action here), and when it [left] (vehicle time since the flight began), and the
 * action's [result] (null: none or skipped) after [tries].
 *
 * @property index the waypoint's index in the list of waypoints the flight was given.
 * @property point the waypoint, as flown (its altitude a height above home).
 * @property reached when the vehicle arrived, in vehicle time since the flight began.
 * @property began when the action started, after the vehicle stopped; null when the waypoint has no action.
 * @property left when the vehicle flew on.
 * @property result what the action returned; null when there was no action or a failure was skipped.
 * @property tries how many times the action ran (0 without an action; more than 1 after retries).
 */
public data class WaypointRecord<R>(
    val index: Int,
    val point: Location,
    val reached: Duration,
    val began: Duration?,
    val left: Duration,
    val result: R?,
    val tries: Int,
    /** The altitude correction in force when it was left (zero without one). */
    val altitudeOffset: Distance = Distance.ZERO,
)

/**
 * What a survey workflow recorded: each photo waypoint's forward record, and each flagged one's
 * backward record with its index into the plan, in the order flown.
 *
 * @property forward the forward pass's records, one per photo waypoint, in order.
 * @property backward the backward pass's records, each with the plan index of the flagged waypoint it revisited.
 */
public data class SurveyRun<F, B>(
    val forward: List<WaypointRecord<Forward<F>>>,
    val backward: List<Pair<Int, WaypointRecord<B>>>,
) {
    /** The plan's indices of the waypoints the forward pass flagged. */
    val flagged: List<Int> get() = forward.filter { it.result?.flagged == true }.map { it.index }
}

/** The action at waypoint [index] failed [tries] times (its last failure is the cause). */
public class WaypointActionFailed(
    /** The waypoint's number. */
    public val index: Int,
    /** How many times the action ran. */
    public val tries: Int,
    cause: Throwable,
) : PodException("the action at waypoint $index failed after $tries ${if (tries == 1) "try" else "tries"}: ${cause.message ?: cause::class.simpleName}", cause)
