package pod.cli.gcs

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import pod.cli.json.SurveyBackward
import pod.cli.json.SurveyMeasured
import pod.cli.json.SurveyOperatorCommand
import pod.cli.json.SurveyPath
import pod.cli.json.SurveyPhoto
import pod.cli.json.SurveyReport
import pod.cli.json.SurveyState
import pod.core.PodException
import pod.core.survey.SurveyPlan
import pod.core.units.Distance
import pod.core.workflow.BackwardRoute
import pod.core.workflow.CommandOutcome
import pod.core.workflow.ControlCommand
import pod.core.workflow.ControlPhase
import pod.core.workflow.ControlReport
import pod.core.workflow.Forward
import pod.core.workflow.MissionControl
import pod.core.workflow.Pass
import pod.core.workflow.WaypointVisit
import pod.mavlink.MavlinkVehicle
import pod.mavlink.workflow.SurveyOperation
import pod.mavlink.workflow.SurveyWorkflow
import pod.sim.SimDetections
import kotlin.time.Duration.Companion.seconds

/**
 * One vehicle's survey mission control, the I-Seed operator's app on the page: a
 * [MissionControl] the page's requests command, served by a [SurveyOperation] flying [vehicle] in
 * the fleet's scope. The forward pass photographs every waypoint and flags those whose photo
 * detected something (a simulated vehicle says what in the photo's `file_url`, [SimDetections]; a
 * real camera that says nothing flags nothing); the backward pass revisits them and measures the
 * range. Commands and reports go to the fleet's log with their event ids; the photos, the
 * backward route and its measurements are kept here for [SurveyFeed].
 */
internal class VehicleSurvey(private val fleet: GcsFleet, private val vehicle: MavlinkVehicle) {
    private val sysid = vehicle.systemId
    val control = MissionControl<SurveyPlan>()

    /** The built path as the page draws it, null before the first build. */
    @Volatile var path: SurveyPath? = null
        private set

    /** The event id of the start of the flight the records below belong to (0: none yet). */
    @Volatile var run: Long = 0
        private set

    /** The forward pass's photos of [run], in the order taken (only the flight's coroutine adds). */
    @Volatile var photos: List<SurveyPhoto> = emptyList()
        private set

    /** The backward pass of [run] once it began. */
    @Volatile var backward: SurveyBackward? = null
        private set

    private var lastReport: ControlReport? = null

    /** Starts serving the operator in the fleet's scope; when that scope is cancelled, a flying vehicle is left holding. */
    fun start() {
        val workflow = SurveyWorkflow(vehicle, timeScale = fleet.timeScale)
        val operation = SurveyOperation(
            vehicle, control.intent, ::report, workflow, ::forward, ::backward,
            readyInTheAir = true, // flown up from the page: ready for a path
        )
        fleet.scope.launch {
            try {
                operation.serve()
            } finally {
                withContext(NonCancellable) { holdIfFlying() }
            }
        }
    }

    private suspend fun holdIfFlying() {
        try {
            withTimeoutOrNull(HOLD_TIMEOUT) { if (vehicle.action.isFlying()) vehicle.action.hold() }
        } catch (e: PodException) {
            // Refused or gone: the autopilot's own failsafes take it from here.
        }
    }

    /** What the page shows of the app now. */
    fun stateEvent(): SurveyState {
        val s = control.state.value
        return when (val p = s.phase) {
            ControlPhase.Waiting -> SurveyState(sysid, "waiting", null, null, null, s.eventId, run)
            ControlPhase.Ready -> SurveyState(sysid, "ready", null, null, null, s.eventId, run)
            ControlPhase.PathBuilt -> SurveyState(sysid, "path_built", null, null, null, s.eventId, run)
            is ControlPhase.Executing -> SurveyState(sysid, "executing", p.pass.word(), p.waypoint, null, s.eventId, run)
            is ControlPhase.Paused -> SurveyState(sysid, "paused", p.pass.word(), p.waypoint, null, s.eventId, run)
            ControlPhase.Finished -> SurveyState(sysid, "finished", null, null, null, s.eventId, run)
            is ControlPhase.Aborted -> SurveyState(sysid, "aborted", null, null, p.reason, s.eventId, run)
        }
    }

    /**
     * Builds [plan] (of [area]) once the vehicle is ready for it: the app waits for the flight side
     * to say so (home and position known). Returns the build's event id.
     */
    suspend fun build(area: SurveyAreaJson, plan: SurveyPlan): Long {
        withTimeoutOrNull(READY_TIMEOUT) { control.state.first { it.phase != ControlPhase.Waiting } }
            ?: throw GcsRequestException("vehicle $sysid is not ready for a survey: no home or position yet")
        val id = command("build") { ControlCommand.Build(it, plan) }
        path = area.pathEvent(sysid, id, plan)
        return id
    }

    /** Sends the operator's [name] command made by [make] with the next event id: that id, or a [GcsRequestException] with the app's reason. */
    fun command(name: String, make: (Long) -> ControlCommand<SurveyPlan>): Long {
        val id = control.nextEventId()
        val outcome = synchronized(this) {
            val outcome = control.command(make(id))
            if (outcome is CommandOutcome.Accepted && name == "start") {
                run = id
                photos = emptyList()
                backward = null
            }
            outcome
        }
        val refused = (outcome as? CommandOutcome.Refused)?.reason
        fleet.logEvent(SurveyOperatorCommand(sysid, name, id, refused == null, refused))
        if (refused != null) throw GcsRequestException("$name refused (event $id): $refused")
        return id
    }

    /** The flight's report: to the app, and to the log when it says something new (the flight repeats it every second). */
    private fun report(r: ControlReport) {
        val counted = control.report(r)
        val fresh = synchronized(this) { (r != lastReport).also { lastReport = r } }
        if (!fresh) return
        if (r.pass() == Pass.BACKWARD && backward == null) planBackward()
        fleet.logEvent(
            when (r) {
                is ControlReport.Vehicle -> SurveyReport(sysid, "vehicle", null, null, r.ready, null, r.eventId, counted)
                is ControlReport.Flying -> SurveyReport(sysid, "flying", r.pass.word(), r.waypoint, null, null, r.eventId, counted)
                is ControlReport.Holding -> SurveyReport(sysid, "holding", r.pass.word(), r.waypoint, null, null, r.eventId, counted)
                is ControlReport.Done -> SurveyReport(sysid, "done", null, null, null, null, r.eventId, counted)
                is ControlReport.Stopped -> SurveyReport(sysid, "stopped", null, null, null, r.reason, r.eventId, counted)
            },
        )
    }

    /**
     * The backward route as the flight plans it when the forward pass ends: the flagged waypoints
     * in [BackwardRoute]'s order from where the vehicle is (the workflow orders them the same way,
     * from the same place, a moment before it reports the pass).
     */
    private fun planBackward() {
        val plan = control.state.value.plan ?: return
        val flagged = photos.filter { it.flagged }.map { it.waypoint }
        val here = vehicle.telemetry.position.value?.location ?: return
        val order = BackwardRoute.order(here, flagged.map { plan.waypoints[it].location }).map { flagged[it] }
        backward = SurveyBackward(sysid, run, order, emptyList())
    }

    /** The forward action: a photo, and what the vehicle says it shows. */
    private suspend fun forward(visit: WaypointVisit): Forward<List<Int>> {
        val photo = try {
            visit.takePhoto()
        } catch (e: CancellationException) {
            throw e
        } catch (e: PodException) {
            null // no camera, or it said nothing in time: nothing detected here
        }
        val seen = photo?.let { SimDetections.parse(it.fileUrl)?.ids }.orEmpty()
        val at = photo?.location ?: visit.point
        photos = photos + SurveyPhoto(sysid, run, visit.index, at.latitude, at.longitude, seen, seen.isNotEmpty(), photo != null)
        return Forward(flagged = seen.isNotEmpty(), value = seen)
    }

    /** The backward action: the range measured over a flagged waypoint, recorded against the plan's nearest flagged one. */
    private suspend fun backward(visit: WaypointVisit): Distance? {
        val range = try {
            visit.measureRange()
        } catch (e: CancellationException) {
            throw e
        } catch (e: PodException) {
            null
        }
        val b = backward ?: return range
        val plan = control.state.value.plan ?: return range
        val waypoint = b.order.minByOrNull { plan.waypoints[it].location.distanceTo(visit.point).meters }
        if (waypoint != null) backward = b.copy(measured = b.measured + SurveyMeasured(waypoint, range?.meters))
        return range
    }

    private fun ControlReport.pass(): Pass? = (this as? ControlReport.Flying)?.pass ?: (this as? ControlReport.Holding)?.pass

    private fun Pass.word() = name.lowercase()

    private companion object {
        /** How long a build waits for the flight side to say the vehicle is ready. */
        val READY_TIMEOUT = 5.seconds

        /** How long the hold sent as the fleet stops may take. */
        val HOLD_TIMEOUT = 3.seconds
    }
}
