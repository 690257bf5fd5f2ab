package pod.mavlink.workflow

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import pod.core.survey.SurveyPlan
import pod.core.vehicle.VehicleType
import pod.core.workflow.AltitudeCorrection
import pod.core.workflow.BackwardRoute
import pod.core.workflow.Forward
import pod.core.workflow.OnFailure
import pod.core.workflow.Pass
import pod.core.workflow.SurveyRun
import pod.core.workflow.WaypointVisit
import pod.mavlink.MavlinkVehicle
import pod.mavlink.queue.QueueFlightConfig
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * The I-Seed survey workflow on one flying vehicle: a *forward* pass stops at every photo waypoint
 * of a [SurveyPlan] and runs the forward action there (a photo and what it detects), then a
 * *backward* pass revisits only the waypoints the forward action flagged — in a short order
 * ([BackwardRoute]), from where the forward pass ended — and runs the backward action (a range
 * reading), then the vehicle returns home (a multirotor lands there). Nothing flagged: no backward
 * pass. Both passes stop and hold at each waypoint ([WaypointFlight]); actions fail by [onFailure].
 */
public class SurveyWorkflow(
    private val vehicle: MavlinkVehicle,
    private val config: QueueFlightConfig = QueueFlightConfig(),
    /** Vehicle seconds per second of the station's clock (a simulator running faster). */
    internal val timeScale: Double = 1.0,
    /** The longest an action may take (vehicle time). */
    private val actionTimeout: Duration = 30.seconds,
    /** What a failed action leads to. */
    private val onFailure: OnFailure = OnFailure.Skip,
    /** How long the flight home may take. */
    internal val homeTimeout: Duration = 15.minutes,
    /** Keeps the forward pass at its height above the ground from the rangefinder, or null. */
    private val altitudeCorrection: AltitudeCorrection? = null,
) {
    /**
     * Flies both passes over [plan] and home; returns what each pass recorded. [paused] holds the
     * vehicle where it is while true; [onProgress] hears which pass and waypoint it is on (the
     * waypoint's index into the pass) and whether it holds for a pause.
     */
    public suspend fun <F, B> run(
        plan: SurveyPlan,
        forward: suspend (WaypointVisit) -> Forward<F>,
        backward: suspend (WaypointVisit) -> B,
        paused: StateFlow<Boolean> = MutableStateFlow(false),
        onProgress: (SurveyProgress) -> Unit = {},
    ): SurveyRun<F, B> {
        val points = plan.waypoints.map { it.location }
        val flight = WaypointFlight(vehicle, config, timeScale)
        fun control(pass: Pass) = FlightControl(paused) { waypoint, holding -> onProgress(SurveyProgress(pass, waypoint, holding)) }
        val forwardRecords = flight.fly(
            points,
            Stop(at = { plan.waypoints[it].photo }, timeout = actionTimeout, onFailure = onFailure, action = forward),
            altitudeCorrection,
            control(Pass.FORWARD),
        ).filter { plan.waypoints[it.index].photo }
        val flagged = forwardRecords.filter { it.result?.flagged == true }.map { it.index }
        val backwardRecords = if (flagged.isEmpty()) {
            emptyList()
        } else {
            val here = vehicle.telemetry.position.value?.location ?: points[flagged.first()]
            val order = BackwardRoute.order(here, flagged.map { points[it] }).map { flagged[it] }
            // Each flagged waypoint at the altitude the forward pass found right there.
            val corrected = order.map { i -> points[i].let { it.copy(altitude = it.altitude + forwardRecords.first { r -> r.index == i }.altitudeOffset) } }
            flight.fly(corrected, Stop(timeout = actionTimeout, onFailure = onFailure, action = backward), control = control(Pass.BACKWARD))
                .map { record -> order[record.index] to record }
        }
        comeHome(paused, onProgress)
        return SurveyRun(forwardRecords, backwardRecords)
    }

    /** Returns home by the autopilot's own procedure (a multirotor lands there), holding where it is while [paused]. */
    private suspend fun comeHome(paused: StateFlow<Boolean>, onProgress: (SurveyProgress) -> Unit) = coroutineScope {
        suspend fun home() {
            paused.first { !it }
            onProgress(SurveyProgress(Pass.HOME, null, holding = false))
            vehicle.action.returnToLaunch()
        }
        home()
        val pausing = launch {
            while (true) {
                paused.first { it }
                vehicle.action.hold()
                onProgress(SurveyProgress(Pass.HOME, null, holding = true))
                home()
            }
        }
        val type = vehicle.identity.value.type
        if (type != VehicleType.FIXED_WING && type != VehicleType.VTOL) vehicle.action.awaitLanded(homeTimeout)
        pausing.cancel()
    }
}

/** Where a [SurveyWorkflow] is: flying (or holding on) [waypoint] of [pass], and whether it holds for a pause. */
public data class SurveyProgress(val pass: Pass, val waypoint: Int?, val holding: Boolean)
