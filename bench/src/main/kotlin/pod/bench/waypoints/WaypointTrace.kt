package pod.bench.waypoints

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import pod.core.units.Location
import pod.sim.SimState
import pod.sim.SimVehicle
import java.util.concurrent.ConcurrentLinkedQueue
import kotlin.math.hypot
import kotlin.time.Duration
import kotlin.time.DurationUnit

/**
 * Everything the simulated vehicle did during one flight, as the simulator published it (every
 * physics tick), stamped with the vehicle's own clock: what the benchmark's figures are computed
 * from, so none of them depends on the ground's view or on wall time.
 */
class Trace private constructor(private val sim: SimVehicle) {
    private val states = ConcurrentLinkedQueue<SimState>()
    private var job: Job? = null

    /** The vehicle's clock now, seconds. */
    fun now(): Double = sim.state.value.time.seconds()

    /** Waits until the vehicle's clock has passed [t] seconds (bounded by the caller). */
    suspend fun awaitTime(t: Double) {
        sim.state.first { it.time.seconds() >= t }
    }

    /** The states recorded so far, oldest first. */
    fun states(): List<SimState> = states.toList()

    /** Forgets what was recorded so far (between flights). */
    fun clear() {
        states.clear()
    }

    /** Stops recording. */
    fun stop() {
        job?.cancel()
    }

    companion object {
        /** Starts recording [sim]'s states in [scope], on the simulator's own thread (nothing published is missed). */
        fun record(scope: CoroutineScope, sim: SimVehicle): Trace = Trace(sim).also { t ->
            t.job = scope.launch(Dispatchers.Unconfined, start = CoroutineStart.UNDISPATCHED) { sim.state.collect { t.states += it } }
        }
    }
}

/** Seconds as a Double. */
fun Duration.seconds(): Double = toDouble(DurationUnit.SECONDS)

/** When an action ran at waypoint [index], on the vehicle's clock (seconds). */
data class ActionRun(val index: Int, val start: Double, val end: Double)

/** One waypoint's figures, vehicle seconds; null where the event never happened. */
data class WaypointTiming(
    val index: Int,
    /** First time the vehicle was within 1 m (3D) of the waypoint. */
    val arrived: Double?,
    val actionStart: Double?,
    val actionEnd: Double?,
    /** First time after the action that the vehicle moved towards the next waypoint at > 0.5 m/s. */
    val moving: Double?,
    /** How far from the waypoint the vehicle was when the action started, m. */
    val offsetAtAction: Double?,
) {
    /** Arrival (within 1 m) to the action's start, s. */
    val before: Double? get() = if (arrived != null && actionStart != null) actionStart - arrived else null

    /** The action's end to moving towards the next waypoint, s. */
    val after: Double? get() = if (actionEnd != null && moving != null) moving - actionEnd else null
}

/** The figures of one flight of the [waypoints] from [start]. */
data class FlightTimings(val waypoints: List<WaypointTiming>, val startedMoving: Double?, val ended: Double?) {
    /** From the vehicle starting to move to the end (last action over, or the last waypoint reached without actions), s. */
    val total: Double? get() = if (startedMoving != null && ended != null) ended - startedMoving else null
}

/** Computes the per-waypoint figures of a flight from its [trace] and the [actions] run. */
object TimingAnalysis {
    /** Within this of a waypoint (3D) counts as arrived. */
    const val ARRIVAL_M = 1.0

    /** Faster than this towards the next waypoint counts as moving on. */
    const val MOVING_MPS = 0.5

    /**
     * Figures of a flight that began at vehicle time [from] with [states], through [waypoints]
     * (AMSL), with [actions] (none for a flight without stops).
     */
    fun analyse(states: List<SimState>, from: Double, waypoints: List<Location>, actions: List<ActionRun>): FlightTimings {
        val flown = states.filter { it.time.seconds() >= from }
        val startedMoving = flown.firstOrNull { it.groundSpeed.metersPerSecond > MOVING_MPS }?.time?.seconds()
        var searchFrom = from
        val timings = waypoints.mapIndexed { i, wp ->
            val action = actions.firstOrNull { it.index == i }
            // Arrival counts only before the action starts: a vehicle that stopped short and acts
            // there never arrived, whatever it passes later.
            val until = action?.start ?: Double.MAX_VALUE
            val arrived = flown.firstOrNull { it.time.seconds() in searchFrom..until && distance(it.location, wp) < ARRIVAL_M }?.time?.seconds()
            val atStart = action?.let { a -> flown.lastOrNull { it.time.seconds() <= a.start } }
            val next = waypoints.getOrNull(i + 1)
            val moving = if (action != null && next != null) {
                flown.firstOrNull { it.time.seconds() >= action.end && towards(it, next) > MOVING_MPS }?.time?.seconds()
            } else {
                null
            }
            searchFrom = action?.end ?: arrived ?: searchFrom
            WaypointTiming(i, arrived, action?.start, action?.end, moving, atStart?.let { distance(it.location, wp) })
        }
        val ended = if (actions.isEmpty()) timings.last().arrived else actions.maxOf { it.end }
        return FlightTimings(timings, startedMoving, ended)
    }

    /** 3D distance, m. */
    fun distance(a: Location, b: Location): Double = hypot(a.distanceTo(b.copy(altitude = a.altitude)).meters, a.altitude.meters - b.altitude.meters)

    /** The vehicle's speed towards [point], m/s (negative: away). */
    private fun towards(s: SimState, point: Location): Double {
        val (n, e) = s.location.northEastTo(point)
        val d = hypot(n.meters, e.meters)
        if (d < 0.01) return 0.0
        return (s.velocityNed.first.metersPerSecond * n.meters + s.velocityNed.second.metersPerSecond * e.meters) / d
    }
}
