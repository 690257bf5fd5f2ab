package pod.bench.queue

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import pod.core.queue.MissionQueue
import pod.core.queue.QueueElement
import pod.core.queue.QueuePattern
import pod.core.queue.WhenEmpty
import pod.core.queue.at
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.mission.MissionItem
import pod.mavlink.queue.QueueFlight
import pod.sim.SimVehicle
import kotlin.math.roundToLong
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/** One change: how long until the vehicle side steered for the new point, and until the ground's calls returned; or why it failed. */
data class Change(val method: ChangeMethod, val size: Int, val condition: LinkCondition, val vehicleMs: Double?, val groundMs: Double?, val error: String? = null)

/**
 * The k-th new point, north and east of home in metres: alternately 400 m north and south of home,
 * so that the vehicle, which turns towards each, stays near home and never reaches one.
 */
internal fun newPoint(k: Int): Pair<Double, Double> = (if (k % 2 == 0) 400.0 else -400.0) to (20.0 * (k % 10) - 100.0)

/** The i-th pending point, north-east of home (never flown to). */
internal fun pendingPoint(i: Int): Pair<Double, Double> = 600.0 + 5.0 * i to 600.0

private fun QueueRig.location(p: Pair<Double, Double>): Location = home.offset(p.first.m, p.second.m)

private fun goto(p: Pair<Double, Double>) = QueueElement(QueuePattern.Goto(at(p.first.m, p.second.m)), altitude = FLIGHT_HEIGHT)

/** Whether the simulator says the autopilot steers for [point] (the altitude aside). */
private fun SimVehicle.steersFor(point: Location): Boolean = state.value.target?.let { it.distanceTo(point).meters < 1.0 } ?: false

/**
 * Times one change: from just before [change] is called until the simulated autopilot steers for
 * [point] ([pod.sim.SimState.target]), stamped on the simulator's own thread as it publishes its
 * state (an unconfined collector runs there), and until [change] returned. Bounded by [limit].
 */
private suspend fun QueueRig.timeChange(method: ChangeMethod, size: Int, condition: LinkCondition, point: Location, limit: Duration, change: suspend () -> Unit): Change = coroutineScope {
    check(!sim.steersFor(point)) { "the vehicle already steers for $point" }
    val seen = CompletableDeferred<TimeSource.Monotonic.ValueTimeMark>()
    val watch = launch(Dispatchers.Unconfined, start = CoroutineStart.UNDISPATCHED) {
        sim.state.first { s -> s.target?.let { it.distanceTo(point).meters < 1.0 } ?: false }
        seen.complete(TimeSource.Monotonic.markNow())
    }
    val start = TimeSource.Monotonic.markNow()
    var ground: Duration? = null
    try {
        withTimeout(limit) {
            change()
            ground = start.elapsedNow()
            seen.await()
        }
        Change(method, size, condition, (seen.await() - start).ms(), ground?.ms())
    } catch (e: TimeoutCancellationException) {
        Change(method, size, condition, null, ground?.ms(), "not at the vehicle within $limit")
    } catch (e: CancellationException) {
        throw e
    } catch (e: Exception) {
        Change(method, size, condition, null, null, "${e::class.simpleName}: ${e.message}")
    } finally {
        watch.cancel()
    }
}

private fun Duration.ms(): Double = inWholeNanoseconds / 1e6

/**
 * The vehicle flies its queue (a current goto and [size] pending ones) in GUIDED; each change is
 * `replaceCurrent(goto(new point))`. [warmUp] changes first, not kept, then [reps].
 */
suspend fun QueueRig.queueChanges(size: Int, condition: LinkCondition, warmUp: Int, reps: Int, gap: Duration, limit: Duration): List<Change> = coroutineScope {
    val queue: MissionQueue = vehicle.queue
    queue.clear()
    queue.append(goto(newPoint(0)))
    repeat(size) { queue.append(goto(pendingPoint(it))) }
    val flight = launch { QueueFlight(vehicle, queue).fly(WhenEmpty.WAIT) }
    try {
        withTimeout(maxOf(limit, SET_UP_LIMIT)) { sim.state.first { sim.steersFor(location(newPoint(0))) } }
        (1..warmUp + reps).map { k ->
            val p = newPoint(k)
            val change = timeChange(ChangeMethod.QUEUE, size, condition, location(p), limit) { queue.replaceCurrent(goto(p)) }
            check(queue.state.value.pending.size == size) { "the queue should still hold $size pending elements" }
            delay(gap)
            change
        }.drop(warmUp)
    } finally {
        flight.cancel()
    }
}

/**
 * The vehicle flies the equivalent mission in AUTO (home, take-off, the current point, the [size]
 * pending ones; item 2 being flown); each change uploads the whole mission again with item 2 moved
 * to the new point, then MISSION_SET_CURRENT 2, which restarts that item on ArduPilot
 * (AP_Mission::set_current_cmd). [warmUp] changes first, not kept, then [reps].
 */
suspend fun QueueRig.reuploadChanges(size: Int, condition: LinkCondition, warmUp: Int, reps: Int, gap: Duration, limit: Duration): List<Change> {
    fun item(seq: Int, command: Int, at: Location?) = MissionItem(
        seq = seq, frame = FRAME_GLOBAL_RELATIVE_ALT_INT, command = command, current = seq == CURRENT_ITEM,
        x = at?.let { (it.latitude * 1e7).roundToLong().toInt() } ?: 0,
        y = at?.let { (it.longitude * 1e7).roundToLong().toInt() } ?: 0,
        z = FLIGHT_HEIGHT.meters.toFloat(),
    )
    fun mission(current: Pair<Double, Double>): List<MissionItem> =
        listOf(item(0, NAV_WAYPOINT, home).copy(frame = 0, z = home.altitude.meters.toFloat()), item(1, NAV_TAKEOFF, null), item(CURRENT_ITEM, NAV_WAYPOINT, location(current))) +
            (0 until size).map { item(CURRENT_ITEM + 1 + it, NAV_WAYPOINT, location(pendingPoint(it))) }

    withTimeout(maxOf(limit, SET_UP_LIMIT)) {
        vehicle.mission.upload(mission(newPoint(0)))
        vehicle.mission.setCurrent(CURRENT_ITEM)
        vehicle.action.setMode("AUTO")
        sim.state.first { sim.steersFor(location(newPoint(0))) }
    }
    return (1..warmUp + reps).map { k ->
        val p = newPoint(k)
        val items = mission(p)
        val change = timeChange(ChangeMethod.REUPLOAD, size, condition, location(p), limit) {
            vehicle.mission.upload(items)
            vehicle.mission.setCurrent(CURRENT_ITEM)
        }
        delay(gap)
        change
    }.drop(warmUp)
}

/** How long setting a case up (the first element flying, or the mission uploaded and flown in AUTO) may take. */
private val SET_UP_LIMIT = 60.seconds

private const val CURRENT_ITEM = 2
private const val FRAME_GLOBAL_RELATIVE_ALT_INT = 6
private const val NAV_WAYPOINT = 16
private const val NAV_TAKEOFF = 22
