package pod.cli.gcs

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.Job
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import pod.cli.json.PageAction
import pod.cli.json.QueueFlightState
import pod.cli.json.queueEvent
import pod.core.PodException
import pod.core.queue.InsertMode
import pod.core.queue.MissionQueue
import pod.core.queue.QueueElement
import pod.core.queue.QueueEntry
import pod.core.queue.WhenEmpty
import pod.mavlink.MavlinkVehicle
import pod.mavlink.queue.QueueFlight
import java.util.concurrent.ConcurrentHashMap
import kotlin.time.Duration.Companion.seconds

/**
 * The mission queues the pages fill, one per vehicle, and their flights: the first time something
 * is added to a vehicle's queue, a [QueueFlight] starts flying it in the fleet's scope and goes on,
 * holding when the queue runs empty ([WhenEmpty.WAIT]), as `pod queue serve` does, until:
 * - the fleet's scope is cancelled (`pod gcs` stopping): the vehicle is left holding;
 * - the vehicle refuses an element, is lost, or another flight holds the queue: the flight ends,
 *   its error is logged and shown ([QueueFlightState]) and the queue is cleared, so the map never
 *   shows as flown what nothing flies;
 * - a page command takes the vehicle over ([stopFlight]): the queue is kept, flown again on resume.
 *
 * The queue is the vehicle's own ([MavlinkVehicle.queue]) unless the fleet runs faster than the
 * clock (a simulator's time scale), where durations must count vehicle time (as `pod queue serve
 * --time-scale` does).
 */
public class QueueDesk internal constructor(private val fleet: GcsFleet) {
    private class Desk(val sysid: Int, val queue: MissionQueue) {
        var flight: Job? = null
        @Volatile var error: String? = null
    }

    private val desks = ConcurrentHashMap<Int, Desk>()

    /** The vehicles that have a queue on this desk, in no order. */
    public val vehicles: Set<Int> get() = desks.keys

    /** Vehicle [sysid]'s queue, made on first use. */
    public fun queue(sysid: Int): MissionQueue = desk(fleet.vehicle(sysid)).queue

    /** Whether vehicle [sysid]'s queue is being flown, and why its last flight ended if it ended by itself. */
    public fun flightState(sysid: Int): QueueFlightState {
        val desk = desks[sysid] ?: return QueueFlightState(sysid, flying = false, error = null)
        return QueueFlightState(sysid, desk.flight?.isActive == true, desk.error)
    }

    /**
     * Adds [element] to vehicle [sysid]'s queue by [mode] and makes sure the queue is flown. A
     * vehicle that is not flying gets nothing added: "take off first".
     */
    public suspend fun insert(sysid: Int, mode: InsertMode, element: QueueElement): QueueEntry {
        val vehicle = fleet.vehicle(sysid)
        val desk = desk(vehicle)
        if (desk.flight?.isActive != true && !vehicle.action.isFlying()) {
            throw GcsRequestException("vehicle $sysid is not flying: take off first, then add to its queue")
        }
        val entry = desk.queue.insert(mode, element)
        fly(vehicle, desk)
        return entry
    }

    /**
     * Flies vehicle [sysid]'s queue again after [stopFlight], when it holds something; false when
     * there is nothing to fly.
     */
    public suspend fun resume(sysid: Int): Boolean {
        val desk = desks[sysid] ?: return false
        if (desk.queue.state.value.current == null) return false
        val vehicle = fleet.vehicle(sysid)
        if (!vehicle.action.isFlying()) throw GcsRequestException("vehicle $sysid is not flying: take off first")
        fly(vehicle, desk)
        return true
    }

    /** Stops flying vehicle [sysid]'s queue (its contents stay) so a page command is not undone by it; true when one was flown. */
    public suspend fun stopFlight(sysid: Int): Boolean {
        val job = desks[sysid]?.flight?.takeIf { it.isActive } ?: return false
        job.cancelAndJoin()
        return true
    }

    private fun desk(vehicle: MavlinkVehicle): Desk = desks.computeIfAbsent(vehicle.systemId) { sysid ->
        val queue = if (fleet.timeScale == 1.0) vehicle.queue else MissionQueue(fleet.station.config.timebase, fleet.timeScale)
        // The queue's own events go to every page's log, in the words `pod queue serve --json` uses.
        fleet.scope.launch { queue.events.collect { fleet.logEvent(queueEvent(sysid, it)) } }
        Desk(sysid, queue)
    }

    private fun fly(vehicle: MavlinkVehicle, desk: Desk): Unit = synchronized(desk) {
        if (desk.flight?.isActive == true) return
        desk.error = null
        desk.flight = fleet.scope.launch { flyUntilEnded(vehicle, desk) }
    }

    private suspend fun flyUntilEnded(vehicle: MavlinkVehicle, desk: Desk) {
        try {
            QueueFlight(vehicle, desk.queue).fly(WhenEmpty.WAIT)
        } catch (e: CancellationException) {
            if (!fleet.scope.isActive) holdOnShutdown(vehicle)
            throw e
        } catch (e: PodException) {
            // QueueNotFlyable, QueueElementRefused, VehicleLost, AutopilotTookControl, QueueBusy: each says what happened.
            val why = e.message ?: e::class.simpleName ?: "failed"
            desk.error = why
            desk.queue.clear()
            fleet.logEvent(PageAction(desk.sysid, "fly the queue", "failed", why))
        }
    }

    /** Leaves a flying vehicle holding where it is when `pod gcs` stops, as `pod queue serve` does on Ctrl-C. */
    private suspend fun holdOnShutdown(vehicle: MavlinkVehicle) = withContext(NonCancellable) {
        withTimeoutOrNull(HOLD_TIMEOUT) { runCatching { if (vehicle.telemetry.armed.value) vehicle.action.hold() } }
    }

    private companion object {
        val HOLD_TIMEOUT = 10.seconds
    }
}

/** The fleet's [QueueDesk]. */
internal val GcsFleet.queues: QueueDesk get() = service(QueueDesk::class) { QueueDesk(it) }
