package pod.mavlink.mission

import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.buffer
import kotlinx.coroutines.flow.channelFlow
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import pod.core.units.toReadable
import pod.core.vehicle.VehicleLost
import pod.core.vehicle.VehicleType
import pod.mavlink.MavlinkVehicle
import pod.mavlink.Wire
import pod.mavlink.command.CommandRejected
import pod.mavlink.command.CommandResult
import pod.mavlink.command.MavCommands
import pod.mavlink.command.VehicleCommand
import pod.mavlink.firmware.Firmware
import pod.mavlink.protocol.RetryPolicy
import pod.mavlink.run

/**
 * Mission, fence and rally lists of one vehicle: upload, download, clear, set the current item.
 *
 * One transfer at a time per vehicle (callers queue). Each operation suspends until it is done and
 * throws a [MissionException] ([MissionRejected], [MissionTimeout], [InvalidMission],
 * [MissionNotConfirmed]) or [VehicleLost] otherwise; cancelling an upload or download tells the
 * vehicle with MISSION_ACK OPERATION_CANCELLED. After an upload that did not complete, the
 * vehicle's actions refuse to start or resume the mission ([MissionHalfWritten]) until an upload
 * completes or the list is cleared.
 */
public class MissionService internal constructor(
    private val vehicle: MavlinkVehicle,
    /** Timeouts and retries of every transfer of this vehicle ([pod.mavlink.VehicleTiming.transfers]). */
    public val timing: TransferTiming,
) {
    private val exclusive = Mutex()
    @Volatile private var servesInOrder = false
    private val appeared = vehicle.clock.markNow() // made with the vehicle, on its first heartbeat
    private val unfinished: MutableSet<MissionType> = java.util.concurrent.ConcurrentHashMap.newKeySet()

    /**
     * Uploads refused with MAV_MISSION_NO_SPACE within [TransferTiming.serviceStartup] of the
     * vehicle's appearance: a vehicle just booted (ArduPilot) has not started its mission storage
     * yet. After the window the refusal stands.
     */
    private val serviceStarting = RetryPolicy(
        SERVICE_RETRY_PAUSE, timing.serviceStartup, RetryPolicy.LastPause.CUT_TO_WINDOW,
        retried = { e -> if (e is MissionRejected && e.result == MissionResult.NO_SPACE) "the vehicle's mission storage to start" else null },
    )

    /**
     * Transfers refused with DENIED, for [TransferTiming.deniedRetry] from the first refusal:
     * ArduPilot refuses every transfer while it holds an unfinished upload (one abandoned by this
     * process or by an earlier one: it ignores the cancelling MISSION_ACK and drops the upload
     * after 8 s without items). A refusal of [operation] that outlasts the wait is thrown, saying so.
     */
    private fun uploadHeld(operation: String) = RetryPolicy(
        SERVICE_RETRY_PAUSE, timing.deniedRetry, RetryPolicy.LastPause.CUT_TO_WINDOW,
        retried = { e -> if (e is MissionRejected && e.result == MissionResult.DENIED) STILL_HOLDING else null },
        giveUp = { e, reason ->
            val refusal = e as MissionRejected
            MissionRejected(refusal.type, refusal.result, refusal.seq, operation, "$reason (refused for ${timing.deniedRetry.toReadable()})")
        },
    )

    /**
     * Uploads [items] as the vehicle's [type] list. When the vehicle's final acknowledgement never
     * arrives, downloads the list back and succeeds only if the vehicle holds what was sent
     * (ArduPilot's item 0, home, excepted); [uploading] does the same and reports progress.
     */
    public suspend fun upload(items: List<MissionItem>, type: MissionType = MissionType.MISSION) {
        MissionValidation.check(type, items)
        write(type, items, partialFrom = null) {}
    }

    /**
     * [upload] as a flow of progress: collecting it runs the upload; it completes when the vehicle
     * holds the list (the last element then counts every item) and throws what [upload] throws.
     */
    public fun uploading(items: List<MissionItem>, type: MissionType = MissionType.MISSION): Flow<TransferProgress> = channelFlow {
        MissionValidation.check(type, items)
        write(type, items, partialFrom = null, changes { trySend(it) })
    }.buffer(Channel.UNLIMITED)

    /**
     * Replaces items `items.first().seq` up to `items.last().seq` of the vehicle's [type] list and
     * leaves the others as they are (MISSION_WRITE_PARTIAL_LIST). The items must be numbered
     * without gaps and lie within the list the vehicle holds. ArduPilot supports this; PX4 ignores
     * the request, so the call ends in [MissionTimeout] there. When the final acknowledgement never
     * arrives, the list is downloaded and the range compared, as for [upload].
     */
    public suspend fun uploadPartial(items: List<MissionItem>, type: MissionType = MissionType.MISSION) {
        require(items.isNotEmpty()) { "a partial upload needs at least one item" }
        val first = items.first().seq
        require(first >= 0) { "the first item's seq must be ≥ 0, was $first" }
        MissionValidation.check(type, items, first)
        write(type, items, first) {}
    }

    /**
     * Runs an [UploadConfirm] (whole list, or from [partialFrom] on), reporting progress to
     * [progress] after each step and once more at the end.
     */
    private suspend fun write(type: MissionType, items: List<MissionItem>, partialFrom: Int?, progress: (TransferProgress) -> Unit) {
        exclusive.withLock {
            // Marked until the vehicle confirms the whole list: an upload that fails or is cancelled
            // half-way may leave it half-written (ArduPilot stores each item as it arrives).
            unfinished += type
            whileHeld("upload", progress) {
                untilServiceUp {
                    val identity = vehicle.identity.value
                    val machine = UploadConfirm(
                        type, items, timing, vehicle.roundTrips.mission(), partialFrom,
                        inOrder = inOrder(), ardupilot = Firmware.of(identity).storesMissionPacked,
                        fixedWing = identity.type == VehicleType.FIXED_WING,
                    )
                    try {
                        vehicle.run(machine, wire(type, cancellable = true)) { progress(machine.progress) }
                    } finally {
                        if (machine.check?.learnedInOrder == true) servesInOrder = true
                    }
                }
            }
            unfinished -= type
            progress(TransferProgress(items.size, items.size))
        }
    }

    /**
     * Throws [MissionHalfWritten] when this service's last upload of [type] did not complete (and no
     * clear followed): starting or resuming would fly whatever part of it the vehicle stored.
     */
    internal fun requireWhole(action: String, type: MissionType = MissionType.MISSION) {
        if (type in unfinished) throw MissionHalfWritten(type, action)
    }

    /** Runs [attempt], waiting out the refusals of a mission storage still starting ([serviceStarting]). */
    private suspend fun <T> untilServiceUp(attempt: suspend () -> T): T = serviceStarting.run(vehicle.clock, appeared, attempt = attempt)

    /** Downloads the vehicle's [type] list; [downloading] does the same and reports progress. */
    public suspend fun download(type: MissionType = MissionType.MISSION): List<MissionItem> =
        exclusive.withLock { whileHeld("download", {}) { downloadLocked(type) {} } }

    /**
     * [download] as a flow of progress: collecting it runs the download; the last element carries
     * the list ([TransferProgress.items]); errors are those of [download].
     */
    public fun downloading(type: MissionType = MissionType.MISSION): Flow<TransferProgress> = channelFlow {
        val report = changes { trySend(it) }
        val items = exclusive.withLock { whileHeld("download", report) { downloadLocked(type, report) } }
        send(TransferProgress(items.size, items.size, items))
    }.buffer(Channel.UNLIMITED)

    /** [report] called only when the progress changed: at most one element per item. */
    private fun changes(report: (TransferProgress) -> Unit): (TransferProgress) -> Unit {
        var last: TransferProgress? = null
        return { progress ->
            if (progress != last) {
                last = progress
                report(progress)
            }
        }
    }

    /**
     * Runs [attempt] (an [operation]), waiting out DENIED while the vehicle holds an unfinished
     * upload ([uploadHeld]), and tells [report] once why it waits.
     */
    private suspend fun <T> whileHeld(operation: String, report: (TransferProgress) -> Unit, attempt: suspend () -> T): T {
        var told = false
        return uploadHeld(operation).run(vehicle.clock, from = null, onWait = { reason ->
            if (!told) report(TransferProgress(0, 0, waiting = reason))
            told = true
        }, attempt = attempt)
    }

    /** Deletes the vehicle's [type] list. */
    public suspend fun clear(type: MissionType = MissionType.MISSION) {
        exclusive.withLock {
            vehicle.run(MissionCommand.clear(type, timing), wire(type, cancellable = false))
            unfinished -= type
        }
    }

    /**
     * Makes item [seq] of the mission the one the vehicle flies next (ArduPilot restarts it when it
     * already is: AP_Mission::set_current_cmd). MISSION_SET_CURRENT is confirmed by a MISSION_CURRENT
     * naming [seq], which cannot tell an answer from the vehicle's periodic report when [seq] is
     * already current: a lost request would look confirmed and an item rewritten by an upload would
     * never be restarted. So that case goes as MAV_CMD_DO_SET_MISSION_CURRENT, which the vehicle
     * acknowledges (ArduPilot: GCS_MAVLINK::handle_command_do_set_mission_current, which calls the same
     * AP_Mission::set_current_cmd); a vehicle that answers UNSUPPORTED gets MISSION_SET_CURRENT.
     */
    public suspend fun setCurrent(seq: Int) {
        require(seq >= 0) { "seq must be ≥ 0, was $seq" }
        if (vehicle.telemetry.missionCurrent.value == seq) {
            try {
                vehicle.commands.send(VehicleCommand(MavCommands.DO_SET_MISSION_CURRENT, param1 = seq.toFloat()))
                return
            } catch (e: CommandRejected) {
                if (e.result != CommandResult.UNSUPPORTED) throw e
            }
        }
        exclusive.withLock { vehicle.run(MissionCommand.setCurrent(seq, timing), wire(MissionType.MISSION, cancellable = false)) }
    }

    // PX4 is known to serve in order; any other vehicle shows it (MAVSDK's vehicle side does), and
    // what one download learned, the next starts from.
    private fun inOrder() = servesInOrder || Firmware.of(vehicle.identity.value).servesMissionInOrder

    private suspend fun downloadLocked(type: MissionType, progress: (TransferProgress) -> Unit): List<MissionItem> {
        val machine = MissionDownload(type, timing, inOrder(), vehicle.roundTrips.mission())
        try {
            return vehicle.run(machine, wire(type, cancellable = true)) { progress(machine.progress) }
        } finally {
            if (machine.learnedInOrder) servesInOrder = true
        }
    }

    /**
     * The vehicle's mission messages (from its autopilot, addressed to us or to everyone), and ours
     * encoded for it. A [cancellable] transfer tells the vehicle when the caller cancels, or it
     * refuses the next transfer (DENIED) until its own timeout: PX4's MavlinkMissionManager (and
     * MAVSDK) drop the transfer on MISSION_ACK OPERATION_CANCELLED; ArduPilot ignores it (see
     * [whileHeld]).
     */
    private fun wire(type: MissionType, cancellable: Boolean): Wire<MissionMessage, MissionMessage> {
        val identity = vehicle.identity.value
        val ourSystem = vehicle.station.config.systemId
        return Wire(
            during = "a ${type.name.lowercase()} transfer",
            pick = { inbound ->
                val message = inbound.message
                if (message == null || inbound.frame.componentId != identity.componentId) {
                    null
                } else {
                    val target = MissionWire.targetSystem(message)
                    // Not ours when addressed to another ground station: that is its exchange.
                    if (target != null && target != 0 && target != ourSystem) null else MissionWire.decode(message)
                }
            },
            encode = { MissionWire.encodeToSend(it, identity.systemId, identity.componentId) },
            onCancel = if (cancellable) listOf(MissionMessage.Ack(type, MissionResult.OPERATION_CANCELLED)) else emptyList(),
        )
    }

    private companion object {
        /** Pause between uploads refused while the vehicle's mission service starts. */
        val SERVICE_RETRY_PAUSE = 500.milliseconds

        /** Why a DENIED transfer waits (see [whileHeld]). */
        const val STILL_HOLDING = "the vehicle is still holding an unfinished upload"
    }
}
