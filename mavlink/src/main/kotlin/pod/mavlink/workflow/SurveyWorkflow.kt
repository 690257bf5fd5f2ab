package pod.mavlink.workflow

import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.FlowCollector
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.selects.select
import pod.core.units.Location
import pod.core.survey.SurveyPlan
import pod.core.vehicle.VehicleType
import pod.core.workflow.AltitudeCorrection
import pod.core.workflow.BackwardRoute
import pod.core.workflow.Forward
import pod.core.workflow.OnFailure
import pod.core.workflow.Pass
import pod.core.workflow.SurveyRun
import pod.core.workflow.WaypointRecord
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
    /** Flies both passes over [plan] and home; returns what each pass recorded. */
    public suspend fun <F, B> run(
        plan: SurveyPlan,
        forward: suspend (WaypointVisit) -> Forward<F>,
        backward: suspend (WaypointVisit) -> B,
    ): SurveyRun<F, B> {
        var run: SurveyRun<F, B>? = null
        flight(plan, forward, backward).collect { if (it is SurveyEvent.Finished) run = it.run }
        return checkNotNull(run) { "the survey ended without its records" }
    }

    /**
     * The flight of [run], cold, for who watches where it is: collecting it flies both passes and
     * home, emitting [SurveyEvent.Progress] at every waypoint it heads for and every hold for a
     * pause (the waypoint's index into its pass) and, last, [SurveyEvent.Finished] with what each
     * pass recorded; failures are thrown from `collect`. [paused] holds the vehicle where it is
     * while true. Events are emitted in the flight's own coroutine, before the flight moves on.
     */
    public fun <F, B> flight(
        plan: SurveyPlan,
        forward: suspend (WaypointVisit) -> Forward<F>,
        backward: suspend (WaypointVisit) -> B,
        paused: StateFlow<Boolean> = MutableStateFlow(false),
    ): Flow<SurveyEvent<F, B>> = flow {
        val points = plan.waypoints.map { it.location }
        val flight = WaypointFlight(vehicle, config, timeScale)

        /** Flies one pass, telling its progress as [pass]'s; returns its records. */
        suspend fun <R> fly(pass: Pass, waypoints: List<Location>, stop: Stop<R>, correction: AltitudeCorrection?): List<WaypointRecord<R>> {
            var records: List<WaypointRecord<R>> = emptyList()
            flight.flight(waypoints, stop, correction, paused).collect { event ->
                when (event) {
                    is WaypointFlightEvent.Progress -> emit(SurveyEvent.Progress(SurveyProgress(pass, event.waypoint, event.holding)))
                    is WaypointFlightEvent.Finished -> records = event.records
                }
            }
            return records
        }

        val forwardRecords = fly(
            Pass.FORWARD,
            points,
            Stop(at = { plan.waypoints[it].photo }, timeout = actionTimeout, onFailure = onFailure, action = forward),
            altitudeCorrection,
        ).filter { plan.waypoints[it.index].photo }
        val flagged = forwardRecords.filter { it.result?.flagged == true }.map { it.index }
        val backwardRecords = if (flagged.isEmpty()) {
            emptyList()
        } else {
            val here = vehicle.telemetry.position.value?.location ?: points[flagged.first()]
            val order = BackwardRoute.order(here, flagged.map { points[it] }).map { flagged[it] }
            // Each flagged waypoint at the altitude the forward pass found right there.
            val corrected = order.map { i -> points[i].let { it.copy(altitude = it.altitude + forwardRecords.first { r -> r.index == i }.altitudeOffset) } }
            fly(Pass.BACKWARD, corrected, Stop(timeout = actionTimeout, onFailure = onFailure, action = backward), correction = null)
                .map { record -> order[record.index] to record }
        }
        comeHome(paused)
        emit(SurveyEvent.Finished(SurveyRun(forwardRecords, backwardRecords)))
    }

    /**
     * Returns home by the autopilot's own procedure (a multirotor lands there), holding where it is
     * while [paused]. The wait for a pause runs beside the wait for the landing, and the progress
     * of a pause is emitted from this coroutine, as a flow must.
     */
    private suspend fun FlowCollector<SurveyEvent<Nothing, Nothing>>.comeHome(paused: StateFlow<Boolean>) = coroutineScope {
        suspend fun home() {
            paused.first { !it }
            emit(SurveyEvent.Progress(SurveyProgress(Pass.HOME, null, holding = false)))
            vehicle.action.returnToLaunch()
        }
        home()
        val type = vehicle.identity.value.type
        if (type == VehicleType.FIXED_WING || type == VehicleType.VTOL) return@coroutineScope
        val landed = async(start = CoroutineStart.UNDISPATCHED) { vehicle.action.awaitLanded(homeTimeout) }
        while (true) {
            val pause = async { paused.first { it } }
            val pausedAgain = select { landed.onAwait { false }; pause.onAwait { true } }
            if (!pausedAgain) {
                pause.cancel()
                break
            }
            vehicle.action.hold()
            emit(SurveyEvent.Progress(SurveyProgress(Pass.HOME, null, holding = true)))
            home()
        }
    }
}

/** What a [SurveyWorkflow.flight] tells as it flies. */
public sealed interface SurveyEvent<out F, out B> {
    /**
     * Where the flight is now.
     *
     * @property progress the pass, the waypoint and whether it holds.
     */
    public data class Progress(val progress: SurveyProgress) : SurveyEvent<Nothing, Nothing>

    /**
     * The flight is home: what each pass recorded. Always the last event.
     *
     * @property run the records of both passes.
     */
    public data class Finished<F, B>(val run: SurveyRun<F, B>) : SurveyEvent<F, B>
}

/**
 * Where a [SurveyWorkflow] is: flying (or holding on) [waypoint] of [pass], and whether it holds for a pause.
 *
 * @property pass the pass being flown, or [Pass.HOME] on the way home.
 * @property waypoint the index of the waypoint flown to in the pass's waypoints, or null when there is none (on the way home).
 * @property holding true while it holds for a pause.
 */
public data class SurveyProgress(val pass: Pass, val waypoint: Int?, val holding: Boolean)
