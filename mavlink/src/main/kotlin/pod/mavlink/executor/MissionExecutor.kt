package pod.mavlink.executor

import java.util.concurrent.atomic.AtomicBoolean
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeMark
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asSharedFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.mission.Mission
import pod.core.mission.MissionCompletion
import pod.core.mission.MissionStep
import pod.core.platform.MissionEvent
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.LandedState
import pod.core.vehicle.Severity
import pod.core.vehicle.isAirborne
import pod.core.vehicle.isOnGround
import pod.core.vehicle.VehicleLost
import pod.mavlink.MavlinkVehicle
import pod.mavlink.firmware.Firmware
import pod.mavlink.plan.MissionFlavor
import pod.mavlink.plan.MissionPlan
import pod.mavlink.plan.MissionPlanner
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.telemetry.ModeRole
import pod.mavlink.telemetry.RecentNotices
import pod.core.units.toReadable

/**
 * Flies one [mission] on one [vehicle]: replaces the vehicle's list with the plan for its flavour
 * (a vehicle flying its previous mission holds first: ArduPilot will not clear a running mission),
 * arms it right before the start in a mode it arms in (ArduCopter in GUIDED, so AUTO then flies the
 * take-off item; ArduPlane in its hold mode, since a plane left in RTL will not arm), starts it,
 * follows MISSION_CURRENT and MISSION_ITEM_REACHED as mission-step events, and returns when the
 * mission is complete:
 * - [MissionCompletion.LAST_STEP_DONE]: the last step is done (a plane whose mission ends with a
 *   return home: the return item is reached, since it then circles home);
 * - [MissionCompletion.LANDED]: on the ground and disarmed after the last step;
 * - [MissionCompletion.LOITERING]: never. Once the final loiter is the current item and the vehicle
 *   is there, at its height (a plane: established on its circle, see [CompletionRules]), it reports
 *   [MissionEvent.Loitering] and keeps following the vehicle until it is cancelled (Dolphin's
 *   "loiter indefinitely"), failing as ever if the vehicle leaves its mission or is lost.
 *
 * A vehicle already flying is not armed again, nor does its home change. Failures are typed:
 * [MissionNotFlyable] before anything is sent, the transfer and command exceptions of the
 * services, [pod.mavlink.action.ActionException], [VehicleLost] when the vehicle falls silent,
 * [MissionInterrupted] when it leaves its mission mode. Cancelling [run] returns promptly and
 * leaves the vehicle as it is (callers make it safe).
 *
 * One executor runs once.
 */
public class MissionExecutor(
    /** The vehicle that flies. */
    public val vehicle: MavlinkVehicle,
    /** What it flies. */
    public val mission: Mission,
    /** Time limits. */
    public val timing: ExecutorTiming = ExecutorTiming(),
) {
    private val ran = AtomicBoolean(false)
    private val _state = MutableStateFlow(MissionRunState.IDLE)
    private val _progress = MutableStateFlow(MissionProgress(null, 0, mission.steps.size, null))
    private val _events = MutableSharedFlow<MissionEvent>(replay = 2 * mission.steps.size + 3)
    private val _plan = MutableStateFlow<MissionPlan?>(null)

    /** Where the run is. */
    public val state: StateFlow<MissionRunState> = _state.asStateFlow()

    /** How far the vehicle is. */
    public val progress: StateFlow<MissionProgress> = _progress.asStateFlow()

    /** Every event of the run so far (replayed to late collectors), in order. */
    public val events: SharedFlow<MissionEvent> = _events.asSharedFlow()

    /** The plan uploaded, once made. */
    public val plan: StateFlow<MissionPlan?> = _plan.asStateFlow()

    /**
     * The flight, cold: collecting it flies the mission to completion (see the class comment),
     * emitting each event as it happens, in the collector's coroutine, and completes with the
     * mission; failures are thrown from `collect`. Collect it once: one executor runs once.
     */
    public fun run(): Flow<MissionEvent> = flow {
        check(ran.compareAndSet(false, true)) { "a MissionExecutor runs once; make a new one for another flight" }
        try {
            fly { emit(it) }
            _state.value = MissionRunState.COMPLETED
        } catch (e: CancellationException) {
            _state.value = MissionRunState.CANCELLED
            throw e
        } catch (e: Throwable) {
            _state.value = MissionRunState.FAILED
            throw e
        }
    }

    private suspend fun fly(report: suspend (MissionEvent) -> Unit) {
        val identity = vehicle.identity.value
        val firmware = Firmware.of(identity)
        val flavor = firmware.missionFlavor
        if (vehicle.connection.value == ConnectionState.LOST) throw VehicleLost(vehicle.systemId, during)
        val airborne = airborne()
        if (!airborne && firmware.missionNeedsTakeOff && mission.steps.firstOrNull { it !is MissionStep.Action } !is MissionStep.TakeOff) {
            throw MissionNotFlyable(mission.name, "on ${flavor.name} a mission flown from the ground must begin with a take-off")
        }
        val heightNow = vehicle.telemetry.position.value?.relativeAltitude?.takeIf { airborne }
        val plan = MissionPlanner.plan(mission, flavor, awaitHome(), heightNow)
        if (plan.items.size <= flavor.firstItem) throw MissionNotFlyable(mission.name, "it has no step ${flavor.name} flies as a mission item")
        _plan.value = plan
        val emit: suspend (MissionEvent) -> Unit = { event ->
            _events.emit(event)
            report(event)
        }

        _state.value = MissionRunState.UPLOADING
        MissionReplacement.replace(vehicle, plan.items, airborne)
        emit(MissionEvent.Uploaded(mission.steps.size))

        _state.value = MissionRunState.STARTING
        if (!airborne) plan.beforeStart.forEach { vehicle.commands.send(it) }
        vehicle.mission.setCurrent(flavor.firstItem)
        coroutineScope {
            // Subscribe before the start so that no report of the flight is missed.
            val inbox = Channel<Input>(Channel.UNLIMITED)
            launch(start = CoroutineStart.UNDISPATCHED) { vehicle.telemetry.missionCurrent.filterNotNull().collect { inbox.send(Input.Current(it)) } }
            launch(start = CoroutineStart.UNDISPATCHED) { vehicle.telemetry.itemReached.collect { inbox.send(Input.Reached(it)) } }
            launch(start = CoroutineStart.UNDISPATCHED) {
                vehicle.statusTexts.collect { if (it.severity <= Severity.NOTICE) inbox.send(Input.Text(it.text, vehicle.clock.markNow())) }
            }
            launch(start = CoroutineStart.UNDISPATCHED) {
                combine(vehicle.telemetry.position, vehicle.telemetry.landedState, vehicle.telemetry.armed, vehicle.telemetry.mode, vehicle.connection) { p, l, a, m, c ->
                    Input.Vehicle(p, l, a, m?.name, c)
                }.collect { inbox.send(it) }
            }
            if (!airborne) {
                val changes = vehicle.action.armForFlight(MissionReplacement.armingMode(identity))
                if (changes.isNotEmpty()) emit(MissionEvent.Prepared(changes))
            }
            vehicle.action.startMission()
            emit(MissionEvent.Started)
            _state.value = MissionRunState.FLYING
            follow(plan, flavor, airborne, inbox, emit)
            currentCoroutineContext()[kotlinx.coroutines.Job]?.cancelChildren()
        }
    }

    private sealed interface Input {
        data class Current(val seq: Int) : Input
        data class Reached(val seq: Int) : Input
        data class Text(val text: String, val at: TimeMark) : Input
        data class Vehicle(
            val position: pod.core.vehicle.Position?,
            val landed: LandedState,
            val armed: Boolean,
            val mode: String?,
            val connection: ConnectionState,
        ) : Input
    }

    private suspend fun follow(plan: MissionPlan, flavor: MissionFlavor, airborneAtStart: Boolean, inbox: Channel<Input>, emit: suspend (MissionEvent) -> Unit) {
        val tracker = ProgressTracker(plan)
        val rule = CompletionRules.rule(mission, flavor)
        val identity = vehicle.identity.value
        val missionMode = FlightModes.forRole(identity.autopilot, identity.type, ModeRole.MISSION)
        val finalLoiter = mission.steps.last() as? MissionStep.Loiter
        val circle = finalLoiter?.takeIf { flavor.fixedWing }?.let { CircleWatch(it) }
        var seen: Input.Vehicle? = null
        var airborneSeen = airborneAtStart
        var leftMission: TimeMark? = null
        // A failsafe says why before or as it switches mode (ArduPilot's fence: the text, then
        // the mode; PX4: "Failsafe activated"): the latest few lines, for the error.
        val heard = RecentNotices()

        suspend fun carryOut(outputs: List<ProgressTracker.Output>) {
            for (out in outputs) when (out) {
                is ProgressTracker.Output.Event -> {
                    _progress.value = MissionProgress(tracker.currentStep, tracker.next, plan.stepCount, tracker.currentItem.takeIf { it >= 0 })
                    emit(out.event)
                }
                is ProgressTracker.Output.Send -> {
                    out.commands.forEach { vehicle.commands.send(it) }
                    carryOut(tracker.commandsSent(out.step))
                }
            }
            _progress.value = MissionProgress(tracker.currentStep, tracker.next, plan.stepCount, tracker.currentItem.takeIf { it >= 0 })
        }

        var loitering = false

        fun complete(v: Input.Vehicle?): Boolean = when (rule) {
            MissionCompletion.LAST_STEP_DONE -> tracker.allDone
            MissionCompletion.LANDED -> v != null && isOnGround(v.landed, v.position?.relativeAltitude) && !v.armed &&
                (tracker.allDone || (airborneSeen && tracker.currentItem >= tracker.lastStepStart))
            MissionCompletion.LOITERING -> finalLoiter != null && v?.position != null && tracker.next >= plan.stepCount - 1 &&
                tracker.currentItem >= tracker.lastStepStart &&
                (circle?.established(v.position) ?: CompletionRules.loitering(finalLoiter, flavor, v.position))
        }

        while (true) {
            val input = leftMission?.let { left ->
                val remaining = timing.modeGrace - left.elapsedNow()
                withTimeoutOrNull(remaining) { inbox.receive() } ?: throw MissionInterrupted(
                    mission.name, seen?.mode ?: "?", tracker.currentStep,
                    said = heard.within(left.elapsedNow() + TEXTS_BEFORE_SWITCH),
                )
            } ?: inbox.receive()
            when (input) {
                is Input.Text -> heard.add(input.text, input.at)
                is Input.Current -> carryOut(tracker.onCurrent(input.seq))
                is Input.Reached -> carryOut(tracker.onReached(input.seq))
                is Input.Vehicle -> {
                    if (input.connection == ConnectionState.LOST) throw VehicleLost(vehicle.systemId, during)
                    seen = input
                    if (isAirborne(input.landed, input.position?.relativeAltitude, input.armed)) airborneSeen = true
                }
            }
            if (rule == MissionCompletion.LOITERING) {
                if (!loitering && complete(seen)) {
                    loitering = true
                    _state.value = MissionRunState.LOITERING
                    emit(MissionEvent.Loitering(mission.steps.size - 1))
                }
            } else if (complete(seen)) {
                carryOut(tracker.finish())
                return
            }
            seen?.let { v ->
                // Down and disarmed short of completion: a crash, a landing short, someone's disarm.
                if (airborneSeen && !v.armed && !isAirborne(v.landed, v.position?.relativeAltitude, false)) {
                    throw MissionDisarmed(mission.name, tracker.currentStep, heard.within(TEXTS_BEFORE_SWITCH))
                }
            }
            val outOfMission = seen?.mode != null && seen?.mode != missionMode && !tracker.allDone
            leftMission = if (outOfMission) leftMission ?: vehicle.clock.markNow() else null
        }
    }

    private fun airborne(): Boolean = vehicle.telemetry.let {
        isAirborne(it.landedState.value, it.position.value?.relativeAltitude, it.armed.value)
    }

    /** The vehicle's home: HOME_POSITION, or where its position report puts it. */
    private suspend fun awaitHome(): Location {
        vehicle.telemetry.home.value?.let { return it }
        return withTimeoutOrNull(timing.homeTimeout) {
            combine(vehicle.telemetry.home, vehicle.telemetry.position) { home, position ->
                home ?: position?.takeIf { !airborne() }?.let { it.location.copy(altitude = (it.location.altitude.meters - it.relativeAltitude.meters).m) }
            }.filterNotNull().first()
        } ?: throw MissionNotFlyable(mission.name, "the vehicle reported no home within ${timing.homeTimeout.toReadable()}")
    }

    private val during: String get() = "mission \"${mission.name}\""

    private companion object {
        /** How long before the switch a notice may come and still be its reason. */
        val TEXTS_BEFORE_SWITCH = 3.seconds
    }
}
