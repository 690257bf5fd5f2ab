package pod.mavlink.vehicle

import pod.mavlink.mission.ArduPilotMissionStorage
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionMessage
import pod.mavlink.mission.MissionResult
import pod.mavlink.mission.MissionType
import pod.mavlink.protocol.Step
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * Vehicle side of the mission protocol for all three lists, as a pure [VehicleMachine]: feed it
 * the ground station's messages and its timer's expiries with the clock (nanoseconds, any origin),
 * send what each [Step] says and wake it when the step asks ([serve] does all three). Its timer
 * re-requests an upload's awaited item and abandons an upload left silent.
 *
 * The ArduPilot flavour writes each MISSION item into the list as it arrives, as ArduPilot does
 * (MissionItemProtocol::handle_mission_item → MissionItemProtocol_Waypoints::replace_item /
 * append_item → AP_Mission::replace_cmd / add_cmd, after MISSION_COUNT truncated the list to the new
 * count: MissionItemProtocol_Waypoints::truncate), so an upload that stops half-way leaves a
 * half-written mission that can be flown: new items up to where it stopped, old ones after. Its
 * fence and rally lists, and every PX4 list, are replaced only when the transfer completes (PX4
 * MavlinkMissionManager writes to the inactive dataman slot and switches on the final item).
 * ArduPilot-flavoured downloads are stateless (any request, any order); PX4-flavoured ones
 * strictly sequential.
 */
public class MissionServer(
    /** Where the behaviour follows ArduPilot or PX4. */
    public val flavor: MissionServerFlavor,
    /** Most items a list may hold; larger uploads get MAV_MISSION_NO_SPACE. */
    public val maxItems: Int = 1000,
    /** Re-request period; null for the flavour's own (1 s ArduPilot, 250 ms PX4). */
    rerequest: Duration? = null,
    /** ArduPlane rather than ArduCopter: decides what an ArduPilot-flavoured NAV_WAYPOINT keeps (see [ArduPilotMissionStorage]). */
    public val fixedWing: Boolean = false,
    /**
     * Until this time (same clock as the inputs) the ArduPilot flavour answers MISSION_COUNT with
     * MAV_MISSION_NO_SPACE, as ArduPilot does right after boot: MissionItemProtocol::handle_mission_count
     * refuses a count above `max_items()`, which is AP_Mission::num_commands_max(), 0 until the
     * mission library has initialised its storage.
     */
    private val storageReadyAt: Long = Long.MIN_VALUE,
    /**
     * The vehicle's home as an item, read when the ArduPilot flavour writes it over item 0 of an
     * uploaded MISSION; null while there is none. A function, since home moves as the vehicle lives.
     */
    home: () -> MissionItem? = { null },
    /**
     * Whether the vehicle lets [MissionMessage.ClearAll] empty a list now; a refusal is answered
     * MISSION_ACK ERROR. The vehicle decides from its state: ArduPilot refuses to clear a mission
     * it is flying (MissionItemProtocol::handle_mission_clear_all answers ERROR when AP_Mission::clear
     * refuses a MISSION_RUNNING mission while armed).
     */
    private val clearAllowed: (MissionType) -> Boolean = { true },
) : VehicleMachine<MissionMessage, MissionMessage> {
    private val rerequestNanos = (rerequest ?: if (flavor == MissionServerFlavor.ARDUPILOT) 1.seconds else 250.milliseconds).inWholeNanoseconds
    private val giveUpNanos = (if (flavor == MissionServerFlavor.ARDUPILOT) 8.seconds else 5.seconds).inWholeNanoseconds
    private val homeItem = home
    private val lists = HashMap<MissionType, List<MissionItem>>()
    private var upload: Upload? = null
    private var completed: Pair<MissionType, Int>? = null // type and last seq of the latest completed upload
    private var sending: Pair<MissionType, Int>? = null // PX4: the list being downloaded and the next seq it expects
    private var sendingActivity = 0L // PX4: when the download last heard from the ground station

    /** When the timer should wake the server next (same clock as the inputs); [Step.NEVER] when no upload is going. */
    private var wakeAt = Step.NEVER

    private class Upload(val type: MissionType, val base: List<MissionItem>, val start: Int, val end: Int, var expected: Int, var lastActivity: Long) {
        val buffer = base.toMutableList()
    }

    /** Home as the ArduPilot flavour writes it over item 0 (see the constructor's `home`). */
    public val home: MissionItem? get() = homeItem()

    /** The item being executed in the MISSION list. */
    public var current: Int = 0
        private set

    /** Whether an upload (or partial write) is going: the server's timer runs meanwhile. */
    public val uploading: Boolean get() = upload != null

    /** What the vehicle holds in [type]'s list. */
    public fun list(type: MissionType): List<MissionItem> = lists[type].orEmpty()

    /** Replaces [type]'s list directly (as if loaded from storage). */
    public fun load(type: MissionType, items: List<MissionItem>) {
        lists[type] = items.mapIndexed { i, item -> item.copy(seq = i, missionType = type) }
    }

    /** Handles one message from the ground station at time [now]: the replies, and when to wake the server. */
    override fun onMessage(message: MissionMessage, now: Long): Step<MissionMessage, Nothing> = Step(answer(message, now), wakeAt)

    /** Re-requests the expected item, or abandons an upload that has been silent too long. */
    override fun onTimer(now: Long): Step<MissionMessage, Nothing> = Step(timeout(now), wakeAt)

    private fun answer(message: MissionMessage, now: Long): List<MissionMessage> = when (message) {
        is MissionMessage.Count -> onCount(message.type, message.count, now)
        is MissionMessage.WritePartial -> onWritePartial(message, now)
        is MissionMessage.Item -> onItem(message.item, now)
        is MissionMessage.RequestList -> if (busy(message.type)) {
            deny(message.type)
        } else {
            if (flavor == MissionServerFlavor.PX4) {
                sending = message.type to 0
                sendingActivity = now
            }
            listOf(MissionMessage.Count(message.type, list(message.type).size))
        }
        is MissionMessage.Request -> onRequest(message, now)
        is MissionMessage.ClearAll -> if (busy(message.type)) {
            deny(message.type)
        } else if (!clearAllowed(message.type)) {
            listOf(MissionMessage.Ack(message.type, MissionResult.ERROR))
        } else {
            lists.remove(message.type)
            if (message.type == MissionType.MISSION) current = 0
            listOf(MissionMessage.Ack(message.type, MissionResult.ACCEPTED))
        }
        is MissionMessage.SetCurrent -> {
            if (message.seq in list(MissionType.MISSION).indices) current = message.seq
            listOf(MissionMessage.Current(current, list(MissionType.MISSION).size))
        }
        is MissionMessage.Ack -> {
            if (sending?.first == message.type) sending = null
            // PX4 drops an upload on the ground station's MISSION_ACK OPERATION_CANCELLED
            // (MavlinkMissionManager::handle_mission_ack, GETLIST state). ArduPilot's
            // MissionItemProtocol has no MISSION_ACK handler: it goes on re-requesting until its
            // own 8 s timeout (MissionItemProtocol::update, upload_timeout_ms), refusing downloads
            // with DENIED meanwhile; only a new MISSION_COUNT from the same sender restarts it.
            val up = upload
            if (flavor == MissionServerFlavor.PX4 && up != null && message.type == up.type && message.result == MissionResult.OPERATION_CANCELLED) idle()
            emptyList()
        }
        is MissionMessage.Current -> emptyList()
    }

    private fun timeout(now: Long): List<MissionMessage> {
        val up = upload ?: return emptyList()
        if (now - up.lastActivity >= giveUpNanos) {
            idle()
            return if (flavor == MissionServerFlavor.ARDUPILOT) listOf(MissionMessage.Ack(up.type, MissionResult.OPERATION_CANCELLED)) else emptyList()
        }
        wakeAt = now + rerequestNanos
        return listOf(request(up))
    }

    private fun onCount(type: MissionType, count: Int, now: Long): List<MissionMessage> {
        val up = upload
        if (up != null && up.type == type && flavor == MissionServerFlavor.PX4 && up.expected == 0) {
            wakeAt = now + rerequestNanos
            return listOf(request(up)) // PX4: a repeated count before item 0 is a lost request's echo
        }
        if (up != null && up.type != type) return deny(type)
        if (up != null && flavor == MissionServerFlavor.PX4) return listOf(MissionMessage.Ack(type, MissionResult.ERROR)) // "Busy"; goes on
        if (count > maxItems || (flavor == MissionServerFlavor.ARDUPILOT && count > 0 && now < storageReadyAt)) {
            idle()
            return listOf(MissionMessage.Ack(type, MissionResult.NO_SPACE))
        }
        if (count == 0) {
            idle()
            lists.remove(type)
            completed = null
            return listOf(MissionMessage.Ack(type, MissionResult.ACCEPTED))
        }
        if (writesAsItArrives(type)) lists[type] = list(type).take(count)
        return begin(Upload(type, List(count) { placeholder(type, it) }, 0, count - 1, 0, now), now)
    }

    /** ArduPilot stores each MISSION item as it arrives (see [MissionServer]). */
    private fun writesAsItArrives(type: MissionType) = flavor == MissionServerFlavor.ARDUPILOT && type == MissionType.MISSION

    /** Writes [item] into its list at once, replacing or appending, as ArduPilot's AP_Mission does. */
    private fun store(item: MissionItem) {
        val items = list(item.missionType).toMutableList()
        val home = homeItem()
        val kept = if (item.seq == 0 && home != null) home.copy(seq = 0, missionType = MissionType.MISSION) else item.copy(current = false)
        val stored = ArduPilotMissionStorage.stored(kept, fixedWing)
        if (item.seq < items.size) items[item.seq] = stored else items += stored
        lists[item.missionType] = items
    }

    private fun onWritePartial(message: MissionMessage.WritePartial, now: Long): List<MissionMessage> {
        if (flavor == MissionServerFlavor.PX4) return emptyList()
        if (busy(message.type)) return deny(message.type)
        val base = list(message.type)
        if (message.start < 0 || message.end < message.start || message.end >= base.size) {
            return listOf(MissionMessage.Ack(message.type, MissionResult.ERROR))
        }
        return begin(Upload(message.type, base, message.start, message.end, message.start, now), now)
    }

    private fun begin(up: Upload, now: Long): List<MissionMessage> {
        upload = up
        completed = null
        wakeAt = now + rerequestNanos
        return listOf(request(up))
    }

    private fun onItem(item: MissionItem, now: Long): List<MissionMessage> {
        val up = upload
        if (up == null || item.missionType != up.type) {
            val done = completed
            if (done != null && item.missionType == done.first && item.seq == done.second) {
                // The ground station missed our final ACK and repeats the last item.
                return listOf(MissionMessage.Ack(item.missionType, if (flavor == MissionServerFlavor.PX4) MissionResult.ACCEPTED else MissionResult.ERROR))
            }
            return listOf(MissionMessage.Ack(item.missionType, MissionResult.ERROR))
        }
        if (item.seq != up.expected) {
            return if (flavor == MissionServerFlavor.ARDUPILOT) listOf(MissionMessage.Ack(up.type, MissionResult.INVALID_SEQUENCE)) else emptyList()
        }
        val problem = StoredItemChecks.problemWith(item, flavor)
        if (problem != null) {
            idle()
            return listOf(MissionMessage.Ack(up.type, problem))
        }
        up.buffer[item.seq] = item.copy(current = false)
        if (writesAsItArrives(up.type)) store(item)
        up.lastActivity = now
        if (up.expected < up.end) {
            up.expected++
            wakeAt = now + rerequestNanos
            return listOf(request(up))
        }
        commit(up)
        return listOf(MissionMessage.Ack(up.type, MissionResult.ACCEPTED))
    }

    private fun onRequest(request: MissionMessage.Request, now: Long): List<MissionMessage> {
        if (busy(request.type)) return deny(request.type)
        if (flavor == MissionServerFlavor.PX4) {
            // A download left without requests for its protocol timeout is dropped, silently
            // (MavlinkMissionManager::send, "check for timed-out operations": back to IDLE when
            // _action_timeout, 5 s by default, passes without a message).
            if (sending != null && now - sendingActivity >= giveUpNanos) sending = null
            // PX4 serves a download strictly in order: the expected item or a repeat of the last
            // one; anything else ends the transfer with ERROR, and requests while idle are ignored.
            val (type, next) = sending ?: return emptyList()
            if (type != request.type) return emptyList()
            sendingActivity = now
            when (request.seq) {
                next -> sending = type to next + 1
                next - 1 -> Unit
                else -> {
                    sending = null
                    return listOf(MissionMessage.Ack(type, MissionResult.ERROR))
                }
            }
        }
        val items = list(request.type)
        if (request.seq !in items.indices) return listOf(MissionMessage.Ack(request.type, MissionResult.INVALID_SEQUENCE))
        val item = items[request.seq]
        // Asked with the legacy MISSION_REQUEST, ArduPilot and PX4 answer with the legacy MISSION_ITEM
        // (ArduPilot MissionItemProtocol::handle_mission_request; PX4 MavlinkMissionManager sends
        // MISSION_ITEM unless the request was MISSION_REQUEST_INT).
        val answer = if (request.type == MissionType.MISSION) item.copy(current = request.seq == current) else item
        return listOf(MissionMessage.Item(answer, legacy = request.legacy))
    }

    private fun commit(up: Upload) {
        var items = up.buffer.toList()
        if (flavor == MissionServerFlavor.ARDUPILOT) {
            // ArduPilot keeps its own packed form of each item, not what was sent.
            items = items.mapIndexed { i, item -> if (i in up.start..up.end) ArduPilotMissionStorage.stored(item, fixedWing) else item }
        }
        val home = homeItem()
        if (flavor == MissionServerFlavor.ARDUPILOT && up.type == MissionType.MISSION && home != null && items.isNotEmpty()) {
            // AP_Mission::write_home_to_storage: a NAV_WAYPOINT at home, kept like any other item.
            items = listOf(ArduPilotMissionStorage.stored(home.copy(seq = 0, missionType = MissionType.MISSION), fixedWing)) + items.drop(1)
        }
        lists[up.type] = items
        if (up.type == MissionType.MISSION && current >= items.size) current = 0
        completed = up.type to up.end
        idle()
    }

    private fun busy(type: MissionType): Boolean = upload?.type == type

    private fun deny(type: MissionType) = listOf(MissionMessage.Ack(type, MissionResult.DENIED))

    private fun request(up: Upload) = MissionMessage.Request(up.type, up.expected, legacy = flavor == MissionServerFlavor.ARDUPILOT)

    private fun idle() {
        upload = null
        wakeAt = Step.NEVER
    }

    private fun placeholder(type: MissionType, seq: Int) = MissionItem(seq = seq, frame = MissionItem.FRAME_MISSION, command = 0, missionType = type)
}
