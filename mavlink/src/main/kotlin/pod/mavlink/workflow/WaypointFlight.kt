package pod.mavlink.workflow

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.PodException
import pod.core.queue.MissionQueue
import pod.core.queue.QueueElement
import pod.core.queue.QueuePattern
import pod.core.queue.QueuePoint
import pod.core.queue.WhenEmpty
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.workflow.AltitudeCorrection
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
     * says where to stop and what to run there.
     */
    public suspend fun <R> fly(waypoints: List<Location>, stop: Stop<R>, correction: AltitudeCorrection? = null): List<WaypointRecord<R>> = coroutineScope {
        require(waypoints.isNotEmpty()) { "give at least one waypoint" }
        val queue = MissionQueue(vehicle.clock, timeScale)
        val flight = async { QueueFlight(vehicle, queue, config).fly(WhenEmpty.WAIT) }
        // Written by the correction's collector, read by this loop: thread-safe holders.
        val offset = MutableStateFlow(Distance.ZERO)
        val flyingTo = MutableStateFlow<Int?>(null)
        fun goto(index: Int) = QueueElement(
            QueuePattern.Goto(QueuePoint.Global(waypoints[index])),
            altitude = (waypoints[index].altitude + offset.value).takeIf { it.meters > 0 },
        )
        val correcting = correction?.let { c -> launch { correct(c, queue) { change ->
            offset.value += change
            // The waypoint being flown to moves too; the ones after take the offset when appended.
            flyingTo.value?.let { i -> if (!queue.state.value.isEmpty) queue.replaceCurrent(goto(i)) }
        } } }
        try {
            waypoints.indices.map { index ->
                flyingTo.value = index
                queue.append(goto(index))
                // Reached: the queue ran empty (one goto at a time; a corrected altitude replaces it).
                // A flight that fails (a refusal, a lost vehicle) cancels this scope, and its
                // failure is what fly() throws.
                queue.state.first { it.isEmpty }
                flyingTo.value = null
                val reached = queue.now()
                var began: Duration? = null
                val outcome = if (stop.at(index)) {
                    settle()
                    began = queue.now()
                    act(index, waypoints[index], stop)
                } else {
                    null
                }
                WaypointRecord(index, waypoints[index], reached, began, queue.now(), outcome?.first, outcome?.second ?: 0, offset.value)
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
    private suspend fun correct(correction: AltitudeCorrection, queue: MissionQueue, apply: (Distance) -> Unit) {
        try {
            vehicle.action.setMessageInterval(MessageIds.DISTANCE_SENSOR, 200.milliseconds)
        } catch (e: PodException) {
            // A vehicle that will not stream it may send it anyway (PX4 does, at 0.5 Hz); go on.
        }
        vehicle.telemetry.rangefinder.filterNotNull().collect { measured ->
            val altitude = vehicle.telemetry.position.value?.relativeAltitude ?: return@collect
            if (queue.state.value.isEmpty) return@collect // holding for an action: measure while flying
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
        kotlinx.coroutines.withTimeoutOrNull(settleTimeout / timeScale) {
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
                return withTimeout(stop.timeout / timeScale) { stop.action(WaypointVisit(index, point, vehicle)) } to tries
            } catch (e: TimeoutCancellationException) {
                e
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
    /** Whether to stop at waypoint number [index] (from 0). */
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

/** What a failed waypoint action leads to. */
public sealed interface OnFailure {
    /** Record no result and go on to the next waypoint. */
    public data object Skip : OnFailure

    /** Run the action up to [times] more times, then abort. */
    public data class Retry(val times: Int) : OnFailure {
        init {
            require(times in 1..100) { "times must be in 1..100, was $times" }
        }
    }

    /** End the flight with [WaypointActionFailed]. */
    public data object Abort : OnFailure
}

/** What an action knows: which waypoint, where, and the vehicle (to take a photo, read a sensor). */
public class WaypointVisit(
    /** The waypoint's number, from 0. */
    public val index: Int,
    /** Where it is (altitude above home). */
    public val point: Location,
    /** The vehicle holding on it. */
    public val vehicle: MavlinkVehicle,
)

/**
 * One waypoint flown: when it was [reached], when the vehicle had stopped and the action [began]
 * (null: no action here), and when it [left] (vehicle time since the flight began), and the
 * action's [result] (null: none or skipped) after [tries].
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

/** The action at waypoint [index] failed [tries] times (its last failure is the cause). */
public class WaypointActionFailed(
    /** The waypoint's number. */
    public val index: Int,
    /** How many times the action ran. */
    public val tries: Int,
    cause: Throwable,
) : PodException("the action at waypoint $index failed after $tries ${if (tries == 1) "try" else "tries"}: ${cause.message ?: cause::class.simpleName}", cause)
