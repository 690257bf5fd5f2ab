package pod.dsl.survey

import pod.core.engine.Task
import pod.dsl.PodDsl
import pod.core.engine.asSet
import pod.core.platform.PlatformVehicle
import pod.core.platform.SafeState
import pod.core.survey.SurveyPlan
import pod.core.survey.SurveySpacing
import pod.core.units.Angle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.workflow.AltitudeCorrection
import pod.core.workflow.Forward
import pod.core.workflow.MissionControl
import pod.core.workflow.OnFailure
import pod.core.workflow.SurveyArea
import pod.core.workflow.SurveyJob
import pod.core.workflow.SurveySettings
import pod.core.workflow.WaypointVisit
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

// The I-Seed survey workflow as a program's task: a forward pass that stops at every photo
// waypoint of a polygon survey and runs `forward` there, a backward pass that revisits the
// waypoints `forward` flagged and runs `backward`, then home. Bind it to a vehicle with `on`.

/**
 * A survey workflow over [polygon] at [height] above home with tracks [spacing] apart: [forward]
 * runs at every photo waypoint (take a photo, say what it shows, [flag] it to come back), and
 * [backward] at every flagged one on the way back. [options] sets the track angle, timeouts, the
 * failure policy and the altitude correction. Arguments are checked here.
 *
 * ```
 * val survey = surveyWorkflow(field, 30.m, SurveySpacing.Direct(40.m, 30.m),
 *     forward = { val seen = detect(takePhoto()); if (seen.isEmpty()) pass(seen) else flag(seen) },
 *     backward = { measureRange() },
 * ) { onFailure = retry(2) }
 * program { pick(1.drone) { (d) -> survey on d } }
 * ```
 */
public fun <F, B> surveyWorkflow(
    polygon: List<Location>,
    height: Distance,
    spacing: SurveySpacing,
    forward: suspend WaypointVisit.() -> Forward<F>,
    backward: suspend WaypointVisit.() -> B,
    options: SurveyOptions.() -> Unit = {},
): SurveyJob<F, B> {
    val o = SurveyOptions().apply(options)
    return SurveyJob(SurveyArea(polygon, height, spacing, o.trackAngle, o.turnaround), forward, backward, o.settings())
}

/**
 * A survey workflow that serves an operator's app through [control]: it reports the vehicle
 * ready, waits for the operator to build a path and start it, obeys pause, resume and abort, and
 * ends when that flight is home. An abort (or a failure) ends the task with
 * [pod.core.workflow.SurveyAborted], the vehicle sent home.
 */
public fun <F, B> surveyService(
    control: MissionControl<SurveyPlan>,
    forward: suspend WaypointVisit.() -> Forward<F>,
    backward: suspend WaypointVisit.() -> B,
    options: SurveyOptions.() -> Unit = {},
): SurveyJob<F, B> = SurveyJob(null, forward, backward, SurveyOptions().apply(options).settings(), control)

/** A forward result that asks for the waypoint to be revisited. */
public fun <F> flag(value: F): Forward<F> = Forward(flagged = true, value = value)

/** A forward result that does not. */
public fun <F> pass(value: F): Forward<F> = Forward(flagged = false, value = value)

/** Fly [this] workflow on [vehicle]. */
public infix fun SurveyJob<*, *>.on(vehicle: PlatformVehicle): Task = Task.Bound(Task.Survey(this), vehicle.asSet())

/** [this] workflow as a task for a vehicle chosen later; a cancelled flight leaves the vehicle in [onCancel] (null: the program's choice). */
public fun SurveyJob<*, *>.task(onCancel: SafeState? = null): Task = Task.Survey(this, onCancel)

/** The settings of a survey workflow, each with its default. */
@PodDsl
public class SurveyOptions internal constructor() {
    /** The tracks' direction (0°: north–south tracks). */
    public var trackAngle: Angle = 0.deg

    /** How far beyond the polygon a track may run to turn. */
    public var turnaround: Distance = 0.m

    /** The longest an action may take (vehicle time). */
    public var actionTimeout: Duration = 30.seconds

    /** What a failed or timed-out action leads to: [skip], [retry] or [abort]. */
    public var onFailure: OnFailure = OnFailure.Skip

    /** How long the flight home may take (vehicle time). */
    public var homeTimeout: Duration = 15.minutes

    private var correction: AltitudeCorrection? = null

    /** Record nothing for a failed action and go on. */
    public val skip: OnFailure get() = OnFailure.Skip

    /** End the flight when an action fails; the vehicle is made safe. */
    public val abort: OnFailure get() = OnFailure.Abort

    /** Run a failed action up to [times] more times, then abort. */
    public fun retry(times: Int): OnFailure = OnFailure.Retry(times)

    /**
     * Keep the forward pass [target] above the ground by the rangefinder: [tolerance] of drift is
     * allowed, corrected waypoints stay between [minimum] and [maximum] above home.
     */
    public fun correctAltitude(target: Distance, tolerance: Distance = 2.m, minimum: Distance = 5.m, maximum: Distance = 120.m) {
        correction = AltitudeCorrection(target, tolerance, minimum, maximum)
    }

    internal fun settings() = SurveySettings(actionTimeout, onFailure, homeTimeout, correction)
}
