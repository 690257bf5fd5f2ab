package pod.mavlink

import io.dronefleet.mavlink.common.CameraInformation
import io.dronefleet.mavlink.common.Statustext
import io.dronefleet.mavlink.minimal.Heartbeat
import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asSharedFlow
import kotlinx.coroutines.flow.asStateFlow
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.Severity
import pod.core.vehicle.StatusText
import pod.core.vehicle.VehicleIdentity
import pod.mavlink.action.VehicleActions
import pod.mavlink.codec.FrameView
import pod.mavlink.codec.MavFrame
import pod.mavlink.command.CommandService
import pod.mavlink.link.LinkPeer
import pod.mavlink.mission.MissionService
import pod.mavlink.param.ParamService
import pod.mavlink.protocol.RoundTrips
import pod.mavlink.telemetry.HotFields
import pod.mavlink.telemetry.HotMessages
import pod.mavlink.telemetry.StatusTextJoiner
import pod.mavlink.telemetry.VehicleTelemetry
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.TimeMark
import kotlin.time.TimeSource

/** A message from a vehicle: the frame as received and its decoded payload (null for unknown ids). */
public class InboundMessage(
    /** The frame as it arrived. */
    public val frame: MavFrame,
    /** The io.dronefleet message object, or null when Pod's dialect does not know the id. */
    public val message: Any?,
)

/**
 * A vehicle heard on a [GroundStation]'s link, keyed by its MAVLink system id.
 *
 * Its [telemetry] is live state; its [messages] carry everything it sends, for the protocol
 * services (commands, missions, parameters) that later talk to it.
 */
public class MavlinkVehicle internal constructor(
    initial: VehicleIdentity,
    internal val station: GroundStation,
) {
    private val _identity = MutableStateFlow(initial)
    internal val _connection = MutableStateFlow(ConnectionState.CONNECTED)

    /** Held while the station turns [connection] on evidence ([lastHeartbeat] read, or a regaining frame applied). */
    internal val connectionLock = Any()
    private val _messages = MutableSharedFlow<InboundMessage>(
        extraBufferCapacity = 1024,
        onBufferOverflow = BufferOverflow.DROP_OLDEST,
    )
    private val _statusTexts = MutableSharedFlow<StatusText>(
        extraBufferCapacity = 64,
        onBufferOverflow = BufferOverflow.DROP_OLDEST,
    )
    private val gaps = SequenceGaps()
    private val texts = StatusTextJoiner()
    /** The station's clock ([GroundStationConfig.clock]): every time reading about this vehicle. */
    internal val clock: TimeSource get() = station.config.clock

    private val textClock = clock.markNow()

    /** Message ids heard from the autopilot since the station last asked for streams (see [StreamRequests]). */
    internal val heardMessages: MutableSet<Int> = java.util.concurrent.ConcurrentHashMap.newKeySet()

    /** When the last HEARTBEAT came, in ns since [heartbeatOrigin]: a number, so that a heartbeat stores no object. */
    private val heartbeatOrigin: TimeMark = clock.markNow()
    @Volatile private var lastHeartbeatNanos = 0L

    /** When the last HEARTBEAT of its own component came (its creation until the first). */
    internal val lastHeartbeat: TimeMark get() = heartbeatOrigin + lastHeartbeatNanos.nanoseconds
    @Volatile internal var peer: LinkPeer? = null

    /** MAVLink system id, 1..255. */
    public val systemId: Int get() = _identity.value.systemId

    /** Type, autopilot and addresses, as its latest HEARTBEAT said. */
    public val identity: StateFlow<VehicleIdentity> = _identity.asStateFlow()

    /** Whether heartbeats still arrive. */
    public val connection: StateFlow<ConnectionState> = _connection.asStateFlow()

    internal val _awaiting = MutableStateFlow<Awaiting?>(null)

    /**
     * The exchange (command, parameter, mission transfer) this vehicle has left unanswered for a
     * couple of seconds while Pod keeps asking, or null: for a UI to say what it waits for
     * instead of staying silent until the exchange fails.
     */
    public val awaiting: StateFlow<Awaiting?> = _awaiting.asStateFlow()

    /** Live telemetry. */
    public val telemetry: VehicleTelemetry = VehicleTelemetry()

    private val _payloads = MutableStateFlow<Set<String>>(emptySet())

    /**
     * What the vehicle has shown it carries, as the MAVLink camera protocol tells: "camera" once a
     * component of its system sends HEARTBEAT with MAV_TYPE_CAMERA, or CAMERA_INFORMATION arrives
     * (ArduPilot 4.5+ answers MAV_CMD_REQUEST_MESSAGE for it from the autopilot when a camera is
     * configured: ardupilot_wiki dev/source/docs/mavlink-camera.rst; a MAVLink camera component
     * heartbeats on its own, mavlink.io services/camera.md). The station asks for it when the
     * vehicle is found. Nothing is assumed: a vehicle that never says so carries nothing.
     */
    public val payloads: StateFlow<Set<String>> = _payloads.asStateFlow()

    private val timing: VehicleTiming get() = station.config.vehicleTiming

    /** Round-trip estimates every protocol exchange with this vehicle starts from and refines. */
    internal val roundTrips: RoundTrips = RoundTrips(timing) { station.resendFloorNanos }

    /** Upload, download and clear its mission, fence and rally lists. */
    public val mission: MissionService = MissionService(this, timing.transfers)

    /** Send commands and wait for their acknowledgement. */
    public val commands: CommandService = CommandService(this, timing.commands)

    /** Read and write its parameters. */
    public val params: ParamService = ParamService(this, timing.params)

    /** Arm, change mode, take off, land, return, go to, pause and continue, each confirmed. */
    public val action: VehicleActions = VehicleActions(this, timing.actions)

    /**
     * This vehicle's dynamic mission queue (Paparazzi's mission interface): add, replace and skip
     * elements at any time; [pod.mavlink.queue.QueueFlight] (or a program's queue task) flies it.
     * Durations count on the station's clock.
     */
    public val queue: pod.core.queue.MissionQueue by lazy { pod.core.queue.MissionQueue(station.config.timebase) }

    /**
     * Text lines the vehicle sends (STATUSTEXT), as they arrive; a long line sent in chunks comes
     * joined, once its last chunk is in (or, when a chunk is lost, about a second after its first).
     */
    public val statusTexts: SharedFlow<StatusText> = _statusTexts.asSharedFlow()

    /** Every message the vehicle sends (a slow collector loses the oldest beyond 1024 buffered). */
    public val messages: SharedFlow<InboundMessage> = _messages.asSharedFlow()

    /**
     * Protocol exchanges listening in place: each is called on the receive path for every frame,
     * so a reply reaches the exchange's inbox with no hop through a [messages] collector (the
     * command round trip and each upload item pay one thread hand-off, not two). A tap must be
     * quick and must not block.
     */
    private val taps = java.util.concurrent.CopyOnWriteArrayList<(InboundMessage) -> Unit>()

    /** How many collect [messages] (read once per frame, so fetched once here). */
    private val messageCollectors: StateFlow<Int> = _messages.subscriptionCount

    /**
     * Whether anyone needs this vehicle's frames as objects ([messages] collectors, [taps]): when
     * nobody does, the hot telemetry messages are read in place ([onHotFrame]), as no one would
     * see the objects (a SharedFlow with no collectors and no replay drops what it is given).
     */
    internal val wantsObjects: Boolean get() = taps.isNotEmpty() || messageCollectors.value > 0

    /** Adds [listener] to the receive path (see [taps]); the returned function removes it. */
    internal fun tap(listener: (InboundMessage) -> Unit): () -> Unit {
        taps += listener
        return { taps -= listener }
    }

    /** Joined status-text lines, to exchanges listening in place (as [taps] are for messages). */
    private val textTaps = java.util.concurrent.CopyOnWriteArrayList<(StatusText) -> Unit>()

    /** Adds [listener] for every joined [statusTexts] line; the returned function removes it. */
    internal fun tapTexts(listener: (StatusText) -> Unit): () -> Unit {
        textTaps += listener
        return { textTaps -= listener }
    }

    /** Called once when the station marks the vehicle lost (see [onLost]). */
    private val lostTaps = java.util.concurrent.CopyOnWriteArrayList<() -> Unit>()

    /**
     * Calls [listener] when the station marks this vehicle lost, or at once if it is lost now (it
     * may then also be called a second time, by a loss that races with this call); the returned
     * function removes it. Lets an exchange fail without a coroutine watching [connection].
     */
    internal fun onLost(listener: () -> Unit): () -> Unit {
        lostTaps += listener
        if (_connection.value == ConnectionState.LOST) listener()
        return { lostTaps -= listener }
    }

    /** The station marked this vehicle lost. */
    internal fun markedLost() {
        for (listener in lostTaps) listener()
    }

    private fun emitText(line: StatusText) {
        _statusTexts.tryEmit(line)
        for (tap in textTaps) tap(line)
    }

    /** Sends [message] (an io.dronefleet message object) to this vehicle. */
    public suspend fun send(message: Any) {
        station.sendTo(this, message)
    }

    /** Called on the station's receive path (a UDP link's own thread) for every frame of this system; see GroundStation.onBytes for what it may touch. */
    internal fun onFrame(frame: MavFrame, message: Any?) {
        gaps.record(frame.componentId, frame.sequence)
        telemetry.onLinkQuality(gaps.received, gaps.lost)
        val own = frame.componentId == _identity.value.componentId
        if (message is Heartbeat) {
            onHeartbeat(own, message.type().value(), message.autopilot().value(), message.baseMode().value(), message.customMode(), message.systemStatus().value())
        } else if (message != null && own) {
            telemetry.onMessage(message)
        }
        if (message is CameraInformation) addPayload(CAMERA)
        if (own) heard(frame.messageId)
        if (message is Statustext) {
            val severity = Severity.entries.getOrElse(message.severity().value()) { Severity.DEBUG }
            val lines = synchronized(texts) { texts.feed(severity, message.text(), message.id(), message.chunkSeq(), textClock.elapsedNow().inWholeNanoseconds, _identity.value.autopilot) }
            lines.forEach(::emitText)
        }
        val inbound = InboundMessage(frame, message)
        for (tap in taps) tap(inbound)
        _messages.tryEmit(inbound)
    }

    /**
     * [onFrame] for a hot telemetry message ([HotMessages]) read in place from [view] into
     * [fields], when nobody [wantsObjects]: the same effects, with no object made unless a
     * telemetry value that is an object (mode, identity) changes.
     */
    internal fun onHotFrame(view: FrameView, fields: HotFields) {
        gaps.record(view.componentId, view.sequence)
        telemetry.onLinkQuality(gaps.received, gaps.lost)
        val own = view.componentId == _identity.value.componentId
        when (view.messageId) {
            MessageIds.HEARTBEAT -> {
                val h = fields.heartbeat.apply { read(view) }
                onHeartbeat(own, h.type, h.autopilot, h.baseMode, h.customMode, h.systemStatus)
            }
            MessageIds.GLOBAL_POSITION_INT -> if (own) {
                val p = fields.position.apply { read(view) }
                telemetry.onGlobalPosition(p.lat, p.lon, p.alt, p.relativeAlt, p.vx, p.vy, p.vz, p.hdg)
            }
            MessageIds.ATTITUDE -> if (own) {
                val a = fields.attitude.apply { read(view) }
                telemetry.onAttitude(a.roll, a.pitch, a.yaw)
            }
            MessageIds.SYS_STATUS -> if (own) {
                val s = fields.sysStatus.apply { read(view) }
                telemetry.onSysStatus(s.batteryRemaining, s.voltageBattery)
            }
            MessageIds.VFR_HUD -> if (own) {
                val h = fields.hud.apply { read(view) }
                telemetry.onHud(h.airspeed, h.groundspeed, h.alt, h.climb, h.heading, h.throttle)
            }
        }
        if (own) heard(view.messageId)
    }

    /** A HEARTBEAT from component [own] (the autopilot's) or another of the system (a camera). */
    private fun onHeartbeat(own: Boolean, type: Int, autopilot: Int, baseMode: Int, customMode: Long, systemStatus: Int) {
        if (own) {
            lastHeartbeatNanos = heartbeatOrigin.elapsedNow().inWholeNanoseconds
            val id = _identity.value
            val vehicleType = MavlinkEnums.vehicleType(type)
            val kind = MavlinkEnums.autopilot(autopilot)
            val updated = if (vehicleType == id.type && kind == id.autopilot) id else id.copy(type = vehicleType, autopilot = kind)
            if (updated !== id) _identity.value = updated
            telemetry.onHeartbeat(updated, customMode, baseMode, systemStatus)
        }
        if (type == MAV_TYPE_CAMERA) addPayload(CAMERA)
    }

    private fun addPayload(name: String) {
        if (name !in _payloads.value) _payloads.value = _payloads.value + name
    }

    /** Notes [messageId] as heard from the autopilot (a look-up, not an insert, once it is there). */
    private fun heard(messageId: Int) {
        if (messageId !in heardMessages) heardMessages += messageId
    }

    /** Delivers chunked lines whose missing chunks are overdue; the station calls it a few times a second. */
    internal fun flushStatusTexts() {
        val lines = synchronized(texts) { texts.flush(textClock.elapsedNow().inWholeNanoseconds) }
        lines.forEach(::emitText)
    }

    override fun toString(): String = "vehicle ${_identity.value.systemId}"

    private companion object {
        /** MAV_TYPE_CAMERA: the HEARTBEAT type of a camera component. */
        const val MAV_TYPE_CAMERA = 30

        /** The payload name a camera is offered under to `pick { payload("camera") }`. */
        const val CAMERA = "camera"
    }
}
