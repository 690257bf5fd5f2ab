package pod.core.workflow

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import pod.core.PodException
import pod.core.survey.CameraTrigger
import pod.core.survey.PolygonSurvey
import pod.core.survey.SurveyPlan
import pod.core.survey.SurveySpacing
import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.deg
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * The area a survey workflow covers, planned when the vehicle is known ([plan] enters it at the
 * corner nearest where the vehicle is). The arguments are those of [PolygonSurvey.plan], checked
 * here so that a bad polygon fails when the program is built, not in flight.
 */
public class SurveyArea(
    /** The operator's polygon (at least 3 points, simple). */
    public val polygon: List<Location>,
    /** The height above home the passes are flown at. */
    public val height: Distance,
    /** The distance between tracks, given or from a camera. */
    public val spacing: SurveySpacing,
    /** The tracks' direction. */
    public val trackAngle: Angle = 0.deg,
    /** How far beyond the polygon a track may run to turn. */
    public val turnaround: Distance = Distance.ZERO,
) {
    init {
        plan(null) // every argument check of the planner, now
    }

    /** The survey's plan, entered nearest [start]: one photo waypoint after another. */
    public fun plan(start: Location?): SurveyPlan =
        PolygonSurvey.plan(polygon, height, spacing, trackAngle, turnaround, start, CameraTrigger.PER_WAYPOINT)
}

/** How a survey workflow flies: action timeouts and failure policy, the way home, and the altitude correction. */
public data class SurveySettings(
    /** The longest an action may take (vehicle time). */
    val actionTimeout: Duration = 30.seconds,
    /** What a failed action leads to. */
    val onFailure: OnFailure = OnFailure.Skip,
    /** How long the flight home may take (vehicle time). */
    val homeTimeout: Duration = 15.minutes,
    /** Keeps the forward pass at its height above the ground from the rangefinder, or null. */
    val altitudeCorrection: AltitudeCorrection? = null,
) {
    init {
        require(actionTimeout.isPositive()) { "actionTimeout must be > 0, was $actionTimeout" }
        require(homeTimeout.isPositive()) { "homeTimeout must be > 0, was $homeTimeout" }
    }
}

/**
 * A survey workflow as the engine runs it (`Task.Survey`): the [area], the forward action run at
 * every photo waypoint, the backward action run at every flagged one, and [settings]. With a
 * [control], the flight serves an operator's app ([MissionControl]): it waits for the operator to
 * build a path and start it, and obeys pause, resume and abort; without one it flies [area] at once.
 *
 * What it recorded is [result] once the vehicle is home; [plan] is the path being flown.
 */
public class SurveyJob<F, B>(
    /** What to survey; null when the operator builds the path ([control] is then required). */
    public val area: SurveyArea?,
    /** Run while the vehicle holds on each photo waypoint: a photo, what it shows, whether to come back. */
    public val forward: suspend WaypointVisit.() -> Forward<F>,
    /** Run while it holds on each flagged waypoint on the way back (a range reading, say). */
    public val backward: suspend WaypointVisit.() -> B,
    /** Timeouts, failure policy and altitude correction. */
    public val settings: SurveySettings = SurveySettings(),
    /** The operator's mission control to serve, or null to fly [area] at once. */
    public val control: MissionControl<SurveyPlan>? = null,
) {
    init {
        require(area != null || control != null) { "give the area to survey, or a mission control for the operator to build it" }
    }

    private val _plan = MutableStateFlow<SurveyPlan?>(null)
    private val _result = MutableStateFlow<SurveyRun<F, B>?>(null)

    /** The path being flown, once planned. */
    public val plan: StateFlow<SurveyPlan?> = _plan.asStateFlow()

    /** What the flight recorded, once the vehicle is home. */
    public val result: StateFlow<SurveyRun<F, B>?> = _result.asStateFlow()

    /** For platforms: the path is [plan]. */
    public fun planned(plan: SurveyPlan) {
        _plan.value = plan
    }

    /** For platforms: the flight ended with [run]. */
    public fun finished(run: SurveyRun<F, B>) {
        _result.value = run
    }
}

/** The platform cannot fly survey workflows. */
public class SurveyUnsupported(
    /** The platform's class name, as the message shows it. */
    public val platform: String,
) : PodException("$platform cannot fly a survey workflow")

/** A survey workflow flies one vehicle, but its task was bound to [vehicles]. */
public class SurveyNeedsOneVehicle(
    /** How many it was bound to. */
    public val vehicles: Int,
) : PodException("a survey workflow flies one vehicle, but the task was bound to $vehicles")

/** The survey flight stopped before it was done, for [reason] (the operator aborted it, or a failure): the vehicle was sent home. */
public class SurveyAborted(
    /** Why. */
    public val reason: String,
) : PodException("the survey stopped: $reason")
