package pod.mavlink.mission

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.delay
import kotlinx.coroutines.withTimeoutOrNull
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.channelFlow
import kotlinx.coroutines.selects.onTimeout
import kotlinx.coroutines.selects.select
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import kotlinx.coroutines.withContext
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleLost
import pod.mavlink.MavlinkVehicle
import pod.mavlink.exchange
import pod.mavlink.MessageTargets
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeMark

/**
 * Mission, fence and rally lists of one vehicle: upload, download, clear, set the current item.
 *
 * One transfer at a time per vehicle (callers queue). Each operation suspends until it is done and
 * throws a [MissionException] ([MissionRejected], [MissionTimeout], [InvalidMission],
 * [MissionNotConfirmed]) or [VehicleLost] otherwise; cancelling an upload or download tells the
 * vehicle with MISSION_ACK OPERATION_CANCELLED.
 */
public class MissionService internal constructor(
    private val vehicle: MavlinkVehicle,
    /** Timeouts and retries of every transfer of this vehicle. */
    public var timing: TransferTiming = TransferTiming(),
) {
    private val exclusive = Mutex()
    @Volatile private var servesInOrder = false
    private val appeared = vehicle.clock.markNow() // made with the vehicle, on its first heartbeat
    private val cancelledUploads = java.util.concurrent.ConcurrentHashMap<MissionType, TimeMark>()
    private var roundTrip: RoundTripEstimator? = null
    private var roundTripTiming: TransferTiming? = null

    /** The round-trip estimate every transfer of this vehicle shares (anew when [timing] changed). */
    private fun roundTrip(): RoundTripEstimator {
        val current = timing
        if (roundTripTiming != current) {
            roundTrip = RoundTripEstimator(current)
            roundTripTiming = current
        }
        return roundTrip!!.also { it.progressed() }
    }

    /**
     * Uploads [items] as the vehicle's [type] list, reporting progress to [onProgress]. When the
     * vehicle's final acknowledgement never arrives, downloads the list back and succeeds only if
     * the vehicle holds what was sent (ArduPilot's item 0, home, excepted).
     */
    public suspend fun upload(
        items: List<MissionItem>,
        type: MissionType = MissionType.MISSION,
        onProgress: (TransferProgress) -> Unit = {},
    ) {
        MissionValidation.check(type, items)
        write(type, items, partialFrom = null, onProgress)
    }

    /**
     * Replaces items `items.first().seq` up to `items.last().seq` of the vehicle's [type] list and
     * leaves the others as they are (MISSION_WRITE_PARTIAL_LIST). The items must be numbered
     * without gaps and lie within the list the vehicle holds. ArduPilot supports this; PX4 ignores
     * the request, so the call ends in [MissionTimeout] there. When the final acknowledgement never
     * arrives, the list is downloaded and the range compared, as for [upload].
     */
    public suspend fun uploadPartial(
        items: List<MissionItem>,
        type: MissionType = MissionType.MISSION,
        onProgress: (TransferProgress) -> Unit = {},
    ) {
        require(items.isNotEmpty()) { "a partial upload needs at least one item" }
        val first = items.first().seq
        require(first >= 0) { "the first item's seq must be ≥ 0, was $first" }
        MissionValidation.check(type, items, first)
        write(type, items, first, onProgress)
    }

    /**
     * Runs an upload (whole list, or from [partialFrom] on); when the final acknowledgement never
     * came, downloads the list and succeeds only if the written range holds what was sent.
     */
    private suspend fun write(type: MissionType, items: List<MissionItem>, partialFrom: Int?, onProgress: (TransferProgress) -> Unit) {
        exclusive.withLock {
            val outcome = try {
                untilServiceUp {
                    val machine = MissionUpload(type, items, timing, roundTrip(), partialFrom)
                    drive(type, cancellable = true, { machine.start() }, machine::onMessage, machine::onTimeout) {
                        onProgress(machine.progress)
                    }
                }
            } catch (e: CancellationException) {
                cancelledUploads[type] = vehicle.clock.markNow()
                throw e
            }
            if (outcome is TransferOutcome.AckMissing) {
                val onBoard = downloadLocked(type) {}
                val written = if (partialFrom == null) onBoard else onBoard.drop(partialFrom).take(items.size)
                if (!sameList(type, written, items, homeFirst = (partialFrom ?: 0) == 0)) throw MissionNotConfirmed(type, onBoard)
            }
            onProgress(TransferProgress(items.size, items.size))
        }
    }

    /**
     * Runs [attempt] again while the vehicle refuses it with MAV_MISSION_NO_SPACE within
     * [TransferTiming.serviceStartup] of its appearance: a vehicle just booted (ArduPilot) has not
     * started its mission storage yet. After the window the refusal stands.
     */
    private suspend fun <T> untilServiceUp(attempt: suspend () -> T): T =
        retryingRefusal(MissionResult.NO_SPACE, { timing.serviceStartup - appeared.elapsedNow() }, attempt)

    /**
     * Runs [attempt] again, pausing [SERVICE_RETRY_PAUSE] between tries, while the vehicle refuses
     * it with [result] and [left] (read after each refusal) is still positive.
     */
    private suspend fun <T> retryingRefusal(result: MissionResult, left: () -> Duration, attempt: suspend () -> T): T {
        while (true) {
            try {
                return attempt()
            } catch (e: MissionRejected) {
                val remaining = left()
                if (e.result != result || remaining <= Duration.ZERO) throw e
                delay(minOf(SERVICE_RETRY_PAUSE, remaining))
            }
        }
    }

    /** [upload] as a flow of progress: collecting it runs the upload; it completes when the vehicle holds the list. */
    public fun uploading(items: List<MissionItem>, type: MissionType = MissionType.MISSION): Flow<TransferProgress> =
        channelFlow { upload(items, type) { trySend(it) } }

    /** Downloads the vehicle's [type] list. */
    public suspend fun download(type: MissionType = MissionType.MISSION, onProgress: (TransferProgress) -> Unit = {}): List<MissionItem> =
        exclusive.withLock { afterOwnCancel(type) { downloadLocked(type, onProgress) } }

    /**
     * Runs [attempt] again while the vehicle answers DENIED within [ABANDONED_UPLOAD_HOLD] of an
     * upload of [type] that this service cancelled: ArduPilot ignores the cancelling MISSION_ACK
     * and holds the abandoned upload until its own timeout (8 s), refusing downloads meanwhile.
     */
    private suspend fun <T> afterOwnCancel(type: MissionType, attempt: suspend () -> T): T =
        retryingRefusal(MissionResult.DENIED, { cancelledUploads[type]?.let { ABANDONED_UPLOAD_HOLD - it.elapsedNow() } ?: Duration.ZERO }, attempt)

    /** [download] as a flow of progress; the list itself comes from [download]. */
    public fun downloading(type: MissionType = MissionType.MISSION): Flow<TransferProgress> =
        channelFlow { download(type) { trySend(it) } }

    /** Deletes the vehicle's [type] list. */
    public suspend fun clear(type: MissionType = MissionType.MISSION) {
        exclusive.withLock {
            val machine = MissionCommand.clear(type, timing)
            drive(type, cancellable = false, machine::start, machine::onMessage, { machine.onTimeout() }) {}
        }
    }

    /** Makes item [seq] of the mission the one the vehicle flies next. */
    public suspend fun setCurrent(seq: Int) {
        require(seq >= 0) { "seq must be ≥ 0, was $seq" }
        exclusive.withLock {
            val machine = MissionCommand.setCurrent(seq, timing)
            drive(MissionType.MISSION, cancellable = false, machine::start, machine::onMessage, { machine.onTimeout() }) {}
        }
    }

    private suspend fun downloadLocked(type: MissionType, onProgress: (TransferProgress) -> Unit): List<MissionItem> {
        // PX4 is known to serve in order; any other vehicle shows it (MAVSDK's vehicle side does),
        // and what one download learned, the next starts from.
        val machine = MissionDownload(type, timing, inOrder = servesInOrder || vehicle.identity.value.autopilot == Autopilot.PX4, roundTrip())
        val outcome = try {
            drive(type, cancellable = true, { machine.start() }, machine::onMessage, machine::onTimeout) { onProgress(machine.progress) }
        } finally {
            if (machine.learnedInOrder) servesInOrder = true
        }
        @Suppress("UNCHECKED_CAST")
        return (outcome as TransferOutcome.Done<List<MissionItem>>).value
    }

    private fun sameList(type: MissionType, onBoard: List<MissionItem>, sent: List<MissionItem>, homeFirst: Boolean = true): Boolean {
        val identity = vehicle.identity.value
        return MissionStorage.holds(
            type, onBoard, sent, ardupilot = identity.autopilot == Autopilot.ARDUPILOT,
            fixedWing = identity.type == pod.core.vehicle.VehicleType.FIXED_WING, homeFirst = homeFirst,
        )
    }

    /**
     * Runs one protocol machine against the vehicle: sends what it says, arms its timer, feeds it
     * the vehicle's mission messages, until it reports an outcome. Returns Done or AckMissing;
     * throws the error of Failed.
     */
    private suspend fun <T> drive(
        type: MissionType,
        cancellable: Boolean,
        start: (Long) -> MissionStep<T>,
        onMessage: (MissionMessage, Long) -> MissionStep<T>,
        onTimeout: (Long) -> MissionStep<T>,
        afterEachStep: () -> Unit,
    ): TransferOutcome<T> {
        val clock = vehicle.clock.markNow()
        fun now() = clock.elapsedNow().inWholeNanoseconds
        val identity = vehicle.identity.value
        val ourSystem = vehicle.station.config.systemId
        return vehicle.exchange("a ${type.name.lowercase()} transfer", pick = { inbound ->
            val message = inbound.message
            val target = message?.let { MessageTargets.targetSystem(it) }
            when {
                message == null || inbound.frame.componentId != identity.componentId -> null
                target != null && target != 0 && target != ourSystem -> null // another ground station's exchange
                else -> MissionWire.decode(message)
            }
        }) { inbox, watch ->
            var deadline = Long.MAX_VALUE
            var step = start(now())
            try {
                while (true) {
                    for (message in step.send) vehicle.send(MissionWire.encode(message, identity.systemId, identity.componentId))
                    if (step.send.isNotEmpty()) watch.sent()
                    when (step.timerNanos) {
                        MissionStep.KEEP_TIMER -> Unit
                        MissionStep.NO_TIMER -> deadline = Long.MAX_VALUE
                        else -> deadline = now() + step.timerNanos
                    }
                    afterEachStep()
                    when (val outcome = step.outcome) {
                        null -> Unit
                        is TransferOutcome.Failed -> throw outcome.error
                        else -> return@exchange outcome
                    }
                    val wait = deadline - now()
                    step = select {
                        inbox.onReceive { onMessage(it, now()) }
                        if (deadline != Long.MAX_VALUE) onTimeout(wait.coerceAtLeast(0).nanoseconds) { onTimeout(now()) }
                    }
                }
                @Suppress("UNREACHABLE_CODE")
                error("unreachable")
            } catch (e: CancellationException) {
                if (cancellable) {
                    // Tell the vehicle, or it refuses the next transfer (DENIED) until its own timeout:
                    // PX4's MavlinkMissionManager (and MAVSDK) drop the transfer on this MISSION_ACK;
                    // ArduPilot ignores it (see afterOwnCancel). Bounded, so a stuck socket cannot
                    // hold up the cancel.
                    withContext(NonCancellable) {
                        withTimeoutOrNull(CANCEL_SEND_LIMIT) {
                            vehicle.send(MissionWire.encode(MissionMessage.Ack(type, MissionResult.OPERATION_CANCELLED), identity.systemId, identity.componentId))
                        }
                    }
                }
                throw e
            }
        }
    }

    private companion object {
        /** Pause between uploads refused while the vehicle's mission service starts. */
        val SERVICE_RETRY_PAUSE = 500.milliseconds

        /** How long after cancelling an upload a DENIED download is taken for the vehicle still holding it (ArduPilot: 8 s). */
        val ABANDONED_UPLOAD_HOLD = 10.seconds

        /** Longest wait to hand the cancelling MISSION_ACK to the link. */
        val CANCEL_SEND_LIMIT = 500.milliseconds
    }
}
