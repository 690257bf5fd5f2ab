package pod.mavlink.workflow

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.FlowCollector
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.launch
import kotlinx.coroutines.flow.merge
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.PodException
import pod.core.queue.MissionQueue
import pod.core.queue.QueueElement
import pod.core.queue.QueuePattern
import pod.core.queue.QueuePoint
import pod.core.queue.WhenEmpty
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.workflow.AltitudeCorrection
import pod.core.workflow.OnFailure
import pod.core.workflow.Photo
import pod.core.workflow.WaypointActionFailed
import pod.core.workflow.WaypointRecord
import pod.core.workflow.WaypointVisit
import pod.mavlink.command.MavCommands
import pod.mavlink.command.VehicleCommand
import pod.mavlink.MessageIds
import pod.mavlink.MavlinkVehicle
import pod.mavlink.queue.QueueFlight
import pod.mavlink.queue.QueueFlightConfig
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * Flies a vehicle through waypoints and, at the ones [Stop.at] chooses, stops, holds and runs a
 * suspend action (a photo, a rangefinder reading, any code) before it goes on: the I-Seed service's
 * `action_job`. Built on the mission queue ([QueueFlight]): each waypoint is a goto, so the vehicle
 * stops on it (a multirotor hovers, a plane circles it) and holds while the queue is empty and the
 * action runs; the next goto is one acknowledged command away.
 *
 * An action that throws or outlasts [Stop.timeout] follows [Stop.onFailure]: skip the waypoint,
 * retry, or abort the flight ([WaypointActionFailed]; the caller, or the engine, makes the vehicle
 * safe). Every waypoint's [WaypointRecord] says when it was reached and left, and what the action
 * returned. The vehicle must be flying.
 */
public class WaypointFlight(
    private val vehicle: MavlinkVehicle,
    private val config: QueueFlightConfig = QueueFlightConfig(),
    /** Vehicle seconds per second of the station's clock (a simulator running faster). */
    private val timeScale: Double = 1.0,
    /** The ground speed (m/s) under which a multirotor counts as stopped on a waypoint. */
    private val settleSpeed: Double = 0.3,
    /** The longest wait for it to stop (vehicle time); the action runs then anyway. */
    private val settleTimeout: Duration = 10.seconds,
) {
    /**
     * Flies [waypoints] (altitudes above home) in order and returns a record per waypoint; [stop]
     * says where to stop and what to run there, [correction] keeps the height above the ground.
     */
    public suspend fun <R> fly(waypoints: List<Location>, stop: Stop<R>, correction: AltitudeCorrection? = null): List<WaypointRecord<R>> {
        var records: List<WaypointRecord<R>>? = null
        flight(waypoints, stop, correction).collect { if (it is WaypointFlightEvent.Finished) records = it.records }
        return checkNotNull(records) { "the flight ended without its records" }
    }

    /**
     * The flight of [fly], cold, for who watches where it is: collecting it flies, emitting
     * [WaypointFlightEvent.Progress] whenever it heads for a waypoint or holds for a pause and, last,
     * [WaypointFlightEvent.Finished] with the records; failures are thrown from `collect`. While
     * [paused] is true the vehicle holds where it is, at its altitude (between waypoints it stops
     * there; on a waypoint it stays once the action is done), and goes on when it turns false.
     *
     * Events are emitted in the flight's own coroutine, so a collector sees each as it happens,
     * before the flight moves on.
     */
    public fun <R> flight(
        waypoints: List<Location>,
        stop: Stop<R>,
        correction: AltitudeCorrection? = null,
        paused: StateFlow<Boolean> = MutableStateFlow(false),
    ): Flow<WaypointFlightEvent<R>> = flow {
        require(waypoints.isNotEmpty()) { "give at least one waypoint" }
        val records = flyThrough(waypoints, stop, correction, paused)
        emit(WaypointFlightEvent.Finished(records))
    }

    /** [flight]'s body, in the collector's coroutine (progress is emitted from here, never from a child). */
    private suspend fun <R> FlowCollector<WaypointFlightEvent<R>>.flyThrough(
        waypoints: List<Location>,
        stop: Stop<R>,
        correction: AltitudeCorrection?,
        paused: StateFlow<Boolean>,
    ): List<WaypointRecord<R>> = coroutineScope {
        val queue = MissionQueue(vehicle.station.config.timebase, timeScale)
        val flight = async { QueueFlight(vehicle, queue, config).fly(WhenEmpty.WAIT) }
        // Written by the correction's collector, read by this loop: thread-safe holders.
        val offset = MutableStateFlow(Distance.ZERO)
        val flyingTo = MutableStateFlow<Int?>(null)
        fun goto(index: Int) = QueueElement(
            QueuePattern.Goto(QueuePoint.Global(waypoints[index])),
            altitude = (waypoints[index].altitude + offset.value).takeIf { it.meters > 0 },
        )
        val correcting = correction?.let { c -> launch { correct(c, queue, paused) { change ->
            offset.value += change
            // The waypoint being flown to moves too; the ones after take the offset when appended.
            flyingTo.value?.let { i -> if (!queue.state.value.isEmpty) queue.replaceCurrent(goto(i)) }
        } } }

        /** Holds where the vehicle is while paused, then heads for waypoint [index] again, or (on it) stays. */
        suspend fun holdWhilePaused(index: Int, onWaypoint: Boolean) {
            if (!paused.value) return
            flyingTo.value = null
            if (!onWaypoint) queue.replaceCurrent(QueueElement(QueuePattern.Hold))
            emit(WaypointFlightEvent.Progress(index, holding = true))
            paused.first { !it }
            emit(WaypointFlightEvent.Progress(index, holding = false))
            if (!onWaypoint) {
                flyingTo.value = index
                queue.replaceCurrent(goto(index))
            }
        }

        /** Flies to waypoint [index], holding on the way whenever paused; returns once it is reached. */
        suspend fun reach(index: Int) {
            flyingTo.value = index
            queue.append(goto(index))
            emit(WaypointFlightEvent.Progress(index, holding = false))
            // Reached: the queue ran empty (one goto at a time; a corrected altitude or a pause
            // replaces it). A flight that fails (a refusal, a lost vehicle) cancels this scope, and
            // its failure is what fly() throws.
            while (true) {
                // A pause outranks an arrival seen at the same moment: it holds there.
                val reached = combine(queue.state, paused) { q, p -> if (p) false else if (q.isEmpty) true else null }.filterNotNull().first()
                if (reached) break
                holdWhilePaused(index, onWaypoint = false)
            }
            flyingTo.value = null
        }

        try {
            waypoints.indices.map { index ->
                reach(index)
                val reached = queue.now()
                var began: Duration? = null
                val outcome = if (stop.at(index)) {
                    settle()
                    began = queue.now()
                    act(index, waypoints[index], stop)
                } else {
                    null
                }
                val left = queue.now()
                holdWhilePaused(index, onWaypoint = true)
                WaypointRecord(index, waypoints[index], reached, began, left, outcome?.first, outcome?.second ?: 0, offset.value)
            }
        } finally {
            correcting?.cancel()
            flight.cancel()
        }
    }

    /**
     * Feeds the rangefinder's readings to [correction] (asking the vehicle for them first: ArduPilot
     * streams DISTANCE_SENSOR only when asked) and passes on each change it decides.
     */
    private suspend fun correct(correction: AltitudeCorrection, queue: MissionQueue, paused: StateFlow<Boolean>, apply: (Distance) -> Unit) {
        try {
            vehicle.action.setMessageInterval(MessageIds.DISTANCE_SENSOR, 200.milliseconds)
        } catch (e: PodException) {
            // A vehicle that will not stream it may send it anyway (PX4 does, at 0.5 Hz); go on.
        }
        vehicle.telemetry.rangefinder.filterNotNull().collect { measured ->
            val altitude = vehicle.telemetry.position.value?.relativeAltitude ?: return@collect
            if (queue.state.value.isEmpty || paused.value) return@collect // holding: measure while flying
            correction.reading(measured, altitude)?.let(apply)
        }
    }

    /**
     * Waits until a multirotor has stopped on the point (ground speed under [settleSpeed], at most
     * [settleTimeout]): arrival counts within a couple of metres, still braking, and a photo or a
     * range reading wants the vehicle still. A plane never stops; it circles the point.
     */
    private suspend fun settle() {
        val type = vehicle.identity.value.type
        if (type == pod.core.vehicle.VehicleType.FIXED_WING || type == pod.core.vehicle.VehicleType.VTOL) return
        withTimeoutOrNull(settleTimeout / timeScale) {
            vehicle.telemetry.position.first { p ->
                p != null && kotlin.math.hypot(p.velocityNorth.metersPerSecond, p.velocityEast.metersPerSecond) < settleSpeed
            }
        }
    }

    /** Runs the action at waypoint [index] under [stop]'s timeout and policy: its result (null when skipped) and how many tries it took. */
    private suspend fun <R> act(index: Int, point: Location, stop: Stop<R>): Pair<R?, Int> {
        var tries = 0
        while (true) {
            tries++
            val failure: Throwable = try {
                // Boxed, so that an action returning null is told apart from one that ran out of time.
                val done = withTimeoutOrNull(stop.timeout / timeScale) { Finished(stop.action(MavlinkWaypointVisit(index, point, vehicle))) }
                if (done != null) return done.value to tries
                WaypointActionTimeout(index, stop.timeout)
            } catch (e: TimeoutCancellationException) {
                e // a time limit of the action's own
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                e
            }
            when (val policy = stop.onFailure) {
                OnFailure.Skip -> return null to tries
                is OnFailure.Retry -> if (tries > policy.times) throw WaypointActionFailed(index, tries, failure)
                OnFailure.Abort -> throw WaypointActionFailed(index, tries, failure)
            }
        }
    }
}

/** Where a [WaypointFlight] stops and what it runs there. */
public class Stop<R>(
    /** Whether to stop at a waypoint, given its index (from 0). */
    public val at: (index: Int) -> Boolean = { true },
    /** The longest an action may take (vehicle time). */
    public val timeout: Duration = 30.seconds,
    /** What a failed or timed-out action leads to. */
    public val onFailure: OnFailure = OnFailure.Skip,
    /** The action, run while the vehicle holds on the waypoint. */
    public val action: suspend (WaypointVisit) -> R,
) {
    init {
        require(timeout.isPositive()) { "timeout must be > 0, was $timeout" }
    }
}

/** A waypoint action's view on a MAVLink vehicle: the [vehicle] itself, for any command or sensor, and its camera. */
public class MavlinkWaypointVisit(
    override val index: Int,
    override val point: Location,
    /** The vehicle holding on the waypoint. */
    public val vehicle: MavlinkVehicle,
) : WaypointVisit {
    override suspend fun takePhoto(timeout: Duration): Photo = vehicle.takePhoto(timeout)

    override suspend fun measureRange(timeout: Duration): Distance = vehicle.measureRange(timeout)
}

/**
 * The distance the downward rangefinder measures (DISTANCE_SENSOR), within [timeout]: asks the
 * vehicle to stream it (ArduPilot sends it only when asked) and takes the latest reading.
 */
public suspend fun MavlinkVehicle.measureRange(timeout: Duration = 5.seconds): Distance {
    try {
        action.setMessageInterval(MessageIds.DISTANCE_SENSOR, 200.milliseconds)
    } catch (e: PodException) {
        // A vehicle that will not stream it may send it anyway (PX4 does, at 0.5 Hz); wait for it.
    }
    return withTimeoutOrNull(timeout) { telemetry.rangefinder.filterNotNull().first() }
        ?: throw NothingReported(systemId, "downward rangefinder reading (DISTANCE_SENSOR)", timeout)
}

/**
 * Takes one photo (MAV_CMD_IMAGE_START_CAPTURE, one image) and returns the first report of it the
 * vehicle sends within [timeout]: CAMERA_IMAGE_CAPTURED (PX4's camera, a MAVLink camera) or
 * CAMERA_FEEDBACK (ArduPilot 4.7, which sends no CAMERA_IMAGE_CAPTURED for its own camera:
 * AP_Camera_Backend::take_picture → prep_mavlink_msg_camera_feedback). A photo confirmed by
 * CAMERA_FEEDBACK has an empty [Photo.fileUrl] and ArduPilot's image number (from 1).
 *
 * @throws NothingReported when neither report comes within [timeout].
 */
public suspend fun MavlinkVehicle.takePhoto(timeout: Duration = 10.seconds): Photo = coroutineScope {
    val next = async(start = CoroutineStart.UNDISPATCHED) { merge(telemetry.imagesCaptured, telemetry.cameraFeedback).first() }
    commands.send(VehicleCommand(MavCommands.IMAGE_START_CAPTURE, param1 = 0f, param2 = 0f, param3 = 1f))
    val image = withTimeoutOrNull(timeout) { next.await() }
        ?: throw NothingReported(systemId, "photo (CAMERA_IMAGE_CAPTURED or CAMERA_FEEDBACK) after IMAGE_START_CAPTURE was accepted", timeout)
    Photo(image.imageIndex, image.location, image.relativeAltitude, image.success, image.fileUrl)
}

/** An action's result, null included. */
private class Finished<R>(val value: R)
