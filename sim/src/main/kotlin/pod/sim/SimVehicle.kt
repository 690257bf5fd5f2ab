package pod.sim

import io.dronefleet.mavlink.common.CommandAck
import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.MavCmd
import io.dronefleet.mavlink.common.MavResult
import io.dronefleet.mavlink.util.EnumValue
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.Job
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.withContext
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.job
import kotlinx.coroutines.launch
import pod.mavlink.MessageTargets
import pod.mavlink.SequenceNumbers
import pod.mavlink.codec.MavFrame
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionMessage
import pod.mavlink.mission.MissionServer
import pod.mavlink.mission.MissionServerFlavor
import pod.mavlink.mission.MissionWire
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.MavlinkLink
import pod.mavlink.telemetry.FlightModes
import kotlin.time.Duration
import kotlin.math.roundToLong
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * A simulated MAVLink vehicle on its own UDP socket, sending to a ground station as SITL's
 * `--out` does: HEARTBEAT at 1 Hz and telemetry streams at rates a ground station can change
 * with MAV_CMD_SET_MESSAGE_INTERVAL.
 *
 * All its coroutines run one at a time (a single-threaded view of the default dispatcher), so its
 * state needs no locks. [start] and [stop] may be called repeatedly: a restarted vehicle comes
 * back from a new local port, as a rebooted autopilot would.
 */
public class SimVehicle(
    /** Identity, behaviour and destination. */
    public val config: SimVehicleConfig,
    private val codec: MessageCodec = MessageCodec.Default,
) {
    private val encoder = FrameEncoder(codec)
    private val sequences = SequenceNumbers()
    private val model = FlightModel(
        SimState(
            location = config.home,
            home = config.home,
            charge = config.initialCharge,
            customMode = FlightModes.customMode(config.autopilot, config.type, defaultModeName()) ?: 0,
        ),
    )
    private val _state = MutableStateFlow(model.state)
    private val rates = MutableStateFlow(config.streamRates)
    private val streams = HashMap<Int, Job>()
    private val bootedAt = TimeSource.Monotonic.markNow()
    private val messages = SimMessages(config, bootedAt)
    private var scope: CoroutineScope? = null
    private var missionTimer: Job? = null
    private var missionTimerAt: Long? = null
    private var missionPeer: Pair<Int, Int>? = null

    /**
     * The vehicle side of the mission protocol: missions, fences and rally points, with the
     * behaviour of the configured autopilot. Its lists survive [stop] and [start], like storage.
     */
    public val missionServer: MissionServer = MissionServer(
        if (config.autopilot == pod.core.vehicle.Autopilot.PX4) MissionServerFlavor.PX4 else MissionServerFlavor.ARDUPILOT,
    )
    private var link: MavlinkLink? = null

    /** The simulated physical state, updated at 20 Hz while running. */
    public val state: StateFlow<SimState> = _state.asStateFlow()

    /** Message id → rate in Hz of what it streams now, as configured or as a ground station asked. */
    public val streamRates: StateFlow<Map<Int, Double>> = rates.asStateFlow()

    /** The local UDP port the vehicle sends from, or null when stopped. */
    public val localPort: Int? get() = link?.localPort

    /** Whether the vehicle is running. */
    public val isRunning: Boolean get() = scope != null

    /**
     * Opens the vehicle's socket and starts its loops as children of [parent]. Throws the link's
     * typed errors for a bad [SimVehicleConfig.gcs].
     */
    @OptIn(ExperimentalCoroutinesApi::class)
    public suspend fun start(parent: CoroutineScope) {
        check(scope == null) { "vehicle ${config.systemId} is already running" }
        val link = MavlinkLink.open(config.gcs)
        val scope = CoroutineScope(
            parent.coroutineContext + SupervisorJob(parent.coroutineContext.job) +
                Dispatchers.Default.limitedParallelism(1) + CoroutineName("sim-${config.systemId}"),
        )
        this.link = link
        this.scope = scope
        scope.launch { receive(link) }
        scope.launch { physics() }
        scope.launch { every(1.seconds) { send(messages.heartbeat(model.state)) } }
        for ((id, hz) in rates.value) restartStream(scope, id, hz)
    }

    /** Stops sending and closes the socket; the ground station will see the vehicle fall silent. */
    public fun stop() {
        scope?.cancel()
        link?.close()
        scope = null
        link = null
        streams.clear()
    }

    private suspend fun physics() {
        val step = 50.milliseconds
        var last = TimeSource.Monotonic.markNow()
        while (true) {
            delay(step)
            val now = TimeSource.Monotonic.markNow()
            model.step((now - last) * config.timeScale)
            last = now
            _state.value = model.state
        }
    }

    private fun restartStream(scope: CoroutineScope, messageId: Int, hz: Double) {
        streams.remove(messageId)?.cancel()
        if (hz <= 0) return
        streams[messageId] = scope.launch(CoroutineName("stream-$messageId")) {
            every((1.0 / hz).seconds) { messages.build(messageId, model.state)?.let { send(it) } }
        }
    }

    private suspend fun receive(link: MavlinkLink) = coroutineScope {
        val decoder = FrameDecoder(codec)
        // The link hands bytes over synchronously; replies need to suspend, so they go through an inbox.
        val inbox = Channel<Pair<MavFrame, Any>>(capacity = 1024, onBufferOverflow = BufferOverflow.DROP_OLDEST)
        launch { for ((frame, message) in inbox) handle(frame, message) }
        link.receive { _, bytes ->
            decoder.feed(bytes) { frame -> codec.decode(frame)?.let { inbox.trySend(frame to it) } }
        }
        inbox.close()
    }

    internal suspend fun handle(frame: MavFrame, message: Any) {
        val target = MessageTargets.targetSystem(message)
        val mission = MissionWire.decode(message)
        if (mission != null && (target == null || target == 0 || target == config.systemId)) {
            serveMission(frame, mission)
            return
        }
        if (message is CommandLong && addressedToUs(message.targetSystem(), message.targetComponent())) {
            val result = when (message.command().value()) {
                MAV_CMD_SET_MESSAGE_INTERVAL -> setInterval(message.param1().toInt(), message.param2())
                else -> MavResult.MAV_RESULT_UNSUPPORTED
            }
            send(
                CommandAck.builder()
                    .command(message.command())
                    .result(EnumValue.of(result))
                    .build(),
            )
        }
    }

    private fun setInterval(messageId: Int, intervalUs: Float): MavResult {
        if (messageId == MessageIds.HEARTBEAT || messages.canBuild(messageId).not()) return MavResult.MAV_RESULT_DENIED
        val hz = when {
            intervalUs < 0 -> 0.0 // -1 disables the stream
            intervalUs == 0f -> config.streamRates[messageId] ?: 1.0 // 0 restores the default
            else -> 1_000_000.0 / intervalUs
        }
        if (hz > 1000) return MavResult.MAV_RESULT_DENIED
        rates.value = rates.value + (messageId to hz)
        scope?.let { restartStream(it, messageId, hz) }
        return MavResult.MAV_RESULT_ACCEPTED
    }

    /** Hands a mission-protocol message to the mission server and sends its replies to the asker. */
    private suspend fun serveMission(frame: MavFrame, message: MissionMessage) {
        missionServer.home = homeItem()
        val replies = missionServer.onMessage(message, clockNanos())
        for (reply in replies) send(MissionWire.encode(reply, frame.systemId, frame.componentId))
        missionPeer = frame.systemId to frame.componentId
        scheduleMissionTimer()
    }

    /**
     * Keeps one timer at the mission server's next deadline. A deadline that did not change keeps
     * its timer: re-arming on every incoming message could cancel a timer in the middle of sending
     * its re-request, and a ground station that keeps talking would then never hear one.
     */
    private fun scheduleMissionTimer() {
        val at = missionServer.nextTimeoutAt
        if (at == missionTimerAt && missionTimer?.isActive == true) return
        missionTimer?.cancel()
        missionTimerAt = at
        if (at == null) return
        val scope = scope ?: return
        missionTimer = scope.launch {
            delay((at - clockNanos()).coerceAtLeast(0).nanoseconds)
            val (system, component) = missionPeer ?: return@launch
            withContext(NonCancellable) {
                val replies = missionServer.onTimeout(clockNanos())
                for (reply in replies) send(MissionWire.encode(reply, system, component))
            }
            missionTimerAt = null
            scheduleMissionTimer()
        }
    }

    private fun homeItem(): MissionItem = config.home.let { home ->
        MissionItem(
            seq = 0, frame = 0, command = 16,
            x = (home.latitude * 1e7).roundToLong().toInt(), y = (home.longitude * 1e7).roundToLong().toInt(),
            z = home.altitude.meters.toFloat(),
        )
    }

    private fun clockNanos(): Long = bootedAt.elapsedNow().inWholeNanoseconds

    private fun addressedToUs(system: Int, component: Int): Boolean =
        (system == 0 || system == config.systemId) && (component == 0 || component == config.componentId)

    private suspend fun send(message: Any) {
        val link = link ?: return
        link.sendToAll(encoder.encode(message, config.systemId, config.componentId, sequences.next(config.systemId, config.componentId)))
    }

    private suspend inline fun every(period: Duration, action: () -> Unit): Nothing {
        while (true) {
            action()
            delay(period)
        }
    }

    private fun defaultModeName(): String = when {
        config.autopilot == pod.core.vehicle.Autopilot.PX4 -> "AUTO.LOITER"
        config.type == pod.core.vehicle.VehicleType.FIXED_WING -> "MANUAL"
        else -> "STABILIZE"
    }

    private companion object {
        const val MAV_CMD_SET_MESSAGE_INTERVAL = 511
    }
}
