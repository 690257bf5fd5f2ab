package pod.mavlink.workflow

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.distinctUntilChanged
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.PodException
import pod.core.survey.SurveyPlan
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType
import pod.core.workflow.ControlPhase
import pod.core.workflow.ControlReport
import pod.core.workflow.ControlIntent
import pod.core.workflow.Forward
import pod.core.workflow.MissionControl
import pod.core.workflow.Pass
import pod.core.workflow.SurveyRun
import pod.core.workflow.WaypointVisit
import pod.mavlink.MavlinkVehicle
import kotlin.math.hypot
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * The flight side of the I-Seed mission control: serves an operator's [MissionControl] with one
 * vehicle. It reports whether the vehicle is ready; on *start* it takes off (when on the ground)
 * and flies the built path as a [SurveyWorkflow]; *pause* holds the vehicle where it is at its
 * altitude, *resume* goes on from there, *abort* stops the flight, holds, then returns home (the
 * autopilot's return never descends before it is over home). Each report carries the event id of
 * the latest command it had applied, so the app never shows a state older than its last command.
 *
 * Started on a vehicle already in the air (the station restarted mid-flight), it does not assume
 * a fresh start: it holds the vehicle (or leaves a return home under way) and reports it stopped,
 * from where the operator can build a new path and start it from the air, or let it come home.
 */
public class SurveyOperation<F, B>(
    private val vehicle: MavlinkVehicle,
    /** What the operator asked for last ([MissionControl.intent]). */
    private val intent: StateFlow<ControlIntent<SurveyPlan>>,
    /** Where reports go ([MissionControl.report], or a link to the app). */
    private val report: (ControlReport) -> Unit,
    /** The survey's flight: its settings, timeouts and altitude correction. */
    private val workflow: SurveyWorkflow,
    private val forward: suspend (WaypointVisit) -> Forward<F>,
    private val backward: suspend (WaypointVisit) -> B,
    /** How often the latest report is sent again (station time). */
    private val resendEvery: Duration = 1.seconds,
    /**
     * Whether a vehicle found in the air is ready for a path (a program that flew it up for this
     * survey) rather than stopped (a station restarted under a flight it knows nothing of).
     */
    private val readyInTheAir: Boolean = false,
) {
    /** Serves [control] directly (the app in the same process); see [readyInTheAir] for a vehicle already flying. */
    public constructor(
        vehicle: MavlinkVehicle,
        control: MissionControl<SurveyPlan>,
        workflow: SurveyWorkflow,
        forward: suspend (WaypointVisit) -> Forward<F>,
        backward: suspend (WaypointVisit) -> B,
        readyInTheAir: Boolean = false,
    ) : this(vehicle, control.intent, { control.report(it) }, workflow, forward, backward, readyInTheAir = readyInTheAir)

    private val _latest = MutableStateFlow<ControlReport>(ControlReport.Vehicle(0, false))
    private val _runs = MutableStateFlow<List<SurveyRun<F, B>>>(emptyList())

    /** The latest report sent: what an app that attaches later starts from ([MissionControl.attachedTo]). */
    public val latest: StateFlow<ControlReport> = _latest.asStateFlow()

    /** What each flight finished so far recorded. */
    public val runs: StateFlow<List<SurveyRun<F, B>>> = _runs.asStateFlow()

    private fun send(r: ControlReport) {
        _latest.value = r
        report(r)
    }

    /**
     * Serves the operator for [flights] flights (started, then finished or aborted), or until
     * cancelled. Between flights it says whether the vehicle is ready, and answers a command that
     * came too late for the flight it was meant for (a pause sent as the vehicle landed) with the
     * flight's outcome stamped with that command's id, so the app does not wait on it forever.
     */
    public suspend fun serve(flights: Int = Int.MAX_VALUE): Unit = coroutineScope {
        require(flights > 0) { "flights must be > 0, was $flights" }
        val applied = MutableStateFlow(intent.value.state.eventId)
        var flown = intent.value.startedBy // a start from before this operation is not flown again
        findState(applied.value)
        // A report can be lost on its way to the app: say the latest again now and then, so the
        // app converges once the link lets it through.
        val repeating = launch {
            while (true) {
                delay(resendEvery)
                report(_latest.value)
            }
        }
        val readiness = launch {
            // Home and position both known: either can come last (over a lossy link, often home).
            combine(vehicle.telemetry.home, vehicle.telemetry.position) { home, position -> home != null && position != null }
                .distinctUntilChanged()
                .collect { ready -> if (_latest.value is ControlReport.Vehicle) send(ControlReport.Vehicle(applied.value, ready)) }
        }
        var count = 0
        while (count < flights) {
            val next = intent.first { it.state.eventId > applied.value }
            applied.value = next.state.eventId
            val phase = next.state.phase
            val unflown = next.startedBy > flown
            when {
                unflown && (phase is ControlPhase.Executing || phase is ControlPhase.Paused) -> {
                    flown = next.startedBy
                    readiness.cancel()
                    applied.value = fly(next.state.plan!!, applied.value, startPaused = phase is ControlPhase.Paused)
                    count++
                }
                unflown && phase is ControlPhase.Aborted -> {
                    // Started and aborted before this side heard of the start: nothing flew.
                    flown = next.startedBy
                    send(ControlReport.Stopped(applied.value, phase.reason))
                    count++
                }
                phase is ControlPhase.Executing || phase is ControlPhase.Paused || phase is ControlPhase.Aborted ->
                    send(restamped(_latest.value, applied.value))
                else -> Unit // built or cancelled a path: the app's state is the command's own
            }
        }
        readiness.cancel()
        repeating.cancel()
    }

    /** [r] as if made after the command [eventId]: a flight's outcome answers a command that came after it. */
    private fun restamped(r: ControlReport, eventId: Long): ControlReport = when (r) {
        is ControlReport.Vehicle -> r.copy(eventId = eventId)
        is ControlReport.Flying -> r.copy(eventId = eventId)
        is ControlReport.Holding -> r.copy(eventId = eventId)
        is ControlReport.Done -> r.copy(eventId = eventId)
        is ControlReport.Stopped -> r.copy(eventId = eventId)
    }

    /** Holds a vehicle found in the air and reports it stopped; on the ground, reports readiness. */
    private suspend fun findState(applied: Long) {
        val airborne = vehicle.telemetry.landedState.value.let { it == LandedState.IN_AIR || it == LandedState.TAKEOFF || it == LandedState.LANDING } ||
            (vehicle.telemetry.armed.value && (vehicle.telemetry.position.value?.relativeAltitude?.meters ?: 0.0) > 1.0)
        if (!airborne) {
            send(ControlReport.Vehicle(applied, vehicle.telemetry.home.value != null && vehicle.telemetry.position.value != null))
            return
        }
        if (readyInTheAir) {
            vehicle.action.hold()
            send(ControlReport.Vehicle(applied, ready = true))
            return
        }
        val mode = vehicle.telemetry.mode.value?.name.orEmpty()
        if ("RTL" in mode || "LAND" in mode) {
            send(ControlReport.Stopped(applied, "found in the air returning home ($mode)"))
        } else {
            vehicle.action.hold()
            send(ControlReport.Stopped(applied, "found in the air with no survey of this station: holding"))
        }
    }

    /** Flies [plan] from the start command [startId] to its end; returns the last event id applied. */
    private suspend fun fly(plan: SurveyPlan, startId: Long, startPaused: Boolean): Long = coroutineScope {
        // Written by the command collector and read where the flight's progress is collected (and
        // the other way round): thread-safe holders.
        val applied = MutableStateFlow(startId)
        val where = MutableStateFlow<SurveyProgress?>(null)
        val paused = MutableStateFlow(startPaused)
        val outcome = MutableStateFlow<Outcome?>(null)
        val flight = launch {
            try {
                send(ControlReport.Flying(applied.value, Pass.FORWARD, null))
                takeOffIfOnGround(vehicle, plan.waypoints.first().location.altitude)
                workflow.flight(plan, forward, backward, paused).collect { event ->
                    when (event) {
                        is SurveyEvent.Progress -> {
                            val p = event.progress
                            where.value = p
                            send(if (p.holding) ControlReport.Holding(applied.value, p.pass, p.waypoint) else ControlReport.Flying(applied.value, p.pass, p.waypoint))
                        }
                        is SurveyEvent.Finished -> _runs.value += event.run
                    }
                }
                outcome.compareAndSet(null, Outcome.Done)
            } catch (e: PodException) {
                outcome.compareAndSet(null, Outcome.Failed(e.message ?: e::class.simpleName.orEmpty()))
            }
        }
        // The operator's commands while it flies: pause, resume, abort.
        val commands = launch {
            intent.collect { i ->
                val s = i.state
                if (s.eventId <= applied.value) return@collect
                applied.value = s.eventId
                val at = where.value
                when (val phase = s.phase) {
                    is ControlPhase.Paused -> {
                        paused.value = true
                        // Before the first waypoint (taking off) the flight reports holding itself, once it does.
                        if (at != null) send(ControlReport.Holding(s.eventId, at.pass, at.waypoint))
                    }
                    is ControlPhase.Executing -> {
                        paused.value = false
                        send(ControlReport.Flying(s.eventId, at?.pass ?: Pass.FORWARD, at?.waypoint))
                    }
                    is ControlPhase.Aborted -> outcome.compareAndSet(null, Outcome.Aborted(phase.reason))
                    else -> Unit // build or cancel: MissionControl refuses them while flying
                }
            }
        }
        val end = outcome.first { it != null }!!
        commands.cancel()
        // A command that came as the flight ended is answered by the outcome.
        intent.value.state.eventId.let { latest -> if (latest > applied.value) applied.value = latest }
        if (end == Outcome.Done) {
            send(ControlReport.Done(applied.value))
        } else {
            flight.cancel()
            flight.join()
            send(ControlReport.Stopped(applied.value, if (end is Outcome.Aborted) end.reason else (end as Outcome.Failed).reason))
            comeHome()
        }
        applied.value
    }

    /** Holds until stopped, then returns home; a multirotor lands there. Never descends in place. */
    private suspend fun comeHome() {
        try {
            vehicle.action.hold()
            withTimeoutOrNull(STOPPING / workflow.timeScale) {
                vehicle.telemetry.position.first { p -> p != null && hypot(p.velocityNorth.metersPerSecond, p.velocityEast.metersPerSecond) < 0.5 }
            }
            vehicle.action.returnToLaunch()
            val type = vehicle.identity.value.type
            if (type != VehicleType.FIXED_WING && type != VehicleType.VTOL) vehicle.action.awaitLanded(workflow.homeTimeout)
        } catch (e: CancellationException) {
            throw e
        } catch (e: PodException) {
            // The report already says stopped; the autopilot's own failsafes take it from here.
        }
    }

    private sealed interface Outcome {
        data object Done : Outcome

        data class Aborted(val reason: String) : Outcome

        data class Failed(val reason: String) : Outcome
    }

    private companion object {
        /** The longest wait for a vehicle to stop before it is sent home (vehicle time). */
        val STOPPING = 15.seconds
    }
}
