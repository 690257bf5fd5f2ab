package pod.mavlink.workflow

import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.core.survey.SurveyPlan
import pod.core.vehicle.VehicleType
import pod.core.workflow.AltitudeCorrection
import pod.core.workflow.BackwardRoute
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.MavCommands
import pod.mavlink.command.VehicleCommand
import pod.mavlink.queue.QueueFlightConfig
import pod.mavlink.telemetry.CapturedImage
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
    private val timeScale: Double = 1.0,
    /** The longest an action may take (vehicle time). */
    private val actionTimeout: Duration = 30.seconds,
    /** What a failed action leads to. */
    private val onFailure: OnFailure = OnFailure.Skip,
    /** How long the flight home may take. */
    private val homeTimeout: Duration = 15.minutes,
    /** Keeps the forward pass at its height above the ground from the rangefinder, or null. */
    private val altitudeCorrection: AltitudeCorrection? = null,
) {
    /** Flies both passes over [plan] and home; returns what each pass recorded. */
    public suspend fun <F, B> run(
        plan: SurveyPlan,
        forward: suspend (WaypointVisit) -> Forward<F>,
        backward: suspend (WaypointVisit) -> B,
    ): SurveyRun<F, B> {
        val points = plan.waypoints.map { it.location }
        val flight = WaypointFlight(vehicle, config, timeScale)
        val forwardRecords = flight.fly(points, Stop(at = { plan.waypoints[it].photo }, timeout = actionTimeout, onFailure = onFailure, action = forward), altitudeCorrection)
            .filter { plan.waypoints[it.index].photo }
        val flagged = forwardRecords.filter { it.result?.flagged == true }.map { it.index }
        val backwardRecords = if (flagged.isEmpty()) {
            emptyList()
        } else {
            val here = vehicle.telemetry.position.value?.location ?: points[flagged.first()]
            val order = BackwardRoute.order(here, flagged.map { points[it] }).map { flagged[it] }
            // Each flagged waypoint at the altitude the forward pass found right there.
            val corrected = order.map { i -> points[i].let { it.copy(altitude = it.altitude + forwardRecords.first { r -> r.index == i }.altitudeOffset) } }
            flight.fly(corrected, Stop(timeout = actionTimeout, onFailure = onFailure, action = backward))
                .map { record -> order[record.index] to record }
        }
        vehicle.action.returnToLaunch()
        val type = vehicle.identity.value.type
        if (type != VehicleType.FIXED_WING && type != VehicleType.VTOL) vehicle.action.awaitLanded(homeTimeout)
        return SurveyRun(forwardRecords, backwardRecords)
    }
}

/** What the forward action says of a waypoint: whether to revisit it ([flagged]) and its [value] (a photo's detections). */
public data class Forward<F>(val flagged: Boolean, val value: F)

/** What a [SurveyWorkflow] recorded: each photo waypoint's forward record, and each flagged one's backward record with its index into the plan. */
public data class SurveyRun<F, B>(
    val forward: List<WaypointRecord<Forward<F>>>,
    val backward: List<Pair<Int, WaypointRecord<B>>>,
)

/**
 * Takes one photo (MAV_CMD_IMAGE_START_CAPTURE, one image) and returns what the vehicle reports of
 * it (CAMERA_IMAGE_CAPTURED), within [timeout].
 */
public suspend fun WaypointVisit.takePhoto(timeout: Duration = 10.seconds): CapturedImage = coroutineScope {
    val next = async(start = CoroutineStart.UNDISPATCHED) { vehicle.telemetry.imagesCaptured.first() }
    vehicle.commands.send(VehicleCommand(MavCommands.IMAGE_START_CAPTURE, param1 = 0f, param2 = 0f, param3 = 1f))
    withTimeout(timeout) { next.await() }
}
