package pod.sim

import pod.mavlink.command.CommandResult
import io.dronefleet.mavlink.common.CommandInt
import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.ParamRequestList
import io.dronefleet.mavlink.common.ParamRequestRead
import io.dronefleet.mavlink.common.ParamSet
import io.dronefleet.mavlink.common.SetMode
import io.dronefleet.mavlink.common.SetupSigning
import pod.core.vehicle.Severity
import pod.sim.signing.ArduPilotSigning
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.DurationUnit
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asSharedFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.job
import kotlinx.coroutines.launch
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec
import pod.mavlink.command.MavCommands.REQUEST_MESSAGE
import pod.mavlink.command.MavCommands.SET_MESSAGE_INTERVAL
import pod.core.time.Timebase
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.MavlinkLink
import pod.mavlink.mission.MissionMessage
import pod.mavlink.mission.MissionType
import pod.mavlink.vehicle.Asker
import pod.mavlink.vehicle.MissionFrames
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.Serving
import pod.mavlink.vehicle.VehicleEncoder
import pod.mavlink.vehicle.serve
import pod.sim.autopilot.CommandRequest
import pod.sim.autopilot.SimAutopilot
import pod.sim.autopilot.SimOutput
import pod.sim.radio.RadioLink
import pod.sim.world.SimWorld

/**
 * A simulated MAVLink vehicle on its own UDP socket, sending to a ground station as SITL's
 * `--out` does: HEARTBEAT at 1 Hz and telemetry streams at rates a ground station can change
 * with MAV_CMD_SET_MESSAGE_INTERVAL, both in the vehicle's own (simulated) time, as SITL run with
 * a speed-up sends them.
 *
 * All its coroutines run one at a time (a single-threaded view of [timebase]'s dispatcher), so its
 * state needs no locks, and every time reading and delay follows [timebase]'s clock: on a test
 * scheduler's timebase with links from a [pod.mavlink.link.MemoryNetwork] ([openLink]) it flies in
 * virtual time (use a [SimVehicleConfig.timeScale] of 1 there: vehicle time is then virtual time).
 * [start] and [stop] may be called repeatedly: a restarted vehicle comes back from a new local
 * port, as a rebooted autopilot would.
 */
public class SimVehicle(
    /** Identity, behaviour and destination. */
    public val config: SimVehicleConfig,
    private val codec: MessageCodec = MessageCodec.Default,
    /** The clock it reads and the dispatcher its coroutines run on. */
    public val timebase: Timebase = Timebase.System,
    /** Opens the vehicle's link to [SimVehicleConfig.gcs]: UDP sockets by default. */
    private val openLink: LinkOpener = LinkOpener.Udp,
) {
    private val encoder = VehicleEncoder(codec, config.systemId, config.componentId)
    private val signing = ArduPilotSigning(config.signingKey, codec)
    private val bootedAt = timebase.clock.markNow()
    private val messages = SimMessages(config, bootedAt) { missionServer.list(MissionType.MISSION).size }
    private val _state: MutableStateFlow<SimState>
    private var scope: CoroutineScope? = null

    /** The mission protocol served while running: its timer lives in the running scope. */
    private var missions: Serving<MissionMessage, MissionMessage>? = null

    /**
     * The vehicle side of the mission protocol: missions, fences and rally points, with the
     * behaviour of the configured autopilot. Its lists survive [stop] and [start], like storage.
     */
    public val missionServer: MissionServer = VehicleMissions.server(config) { autopilot }

    /** The simulated autopilot; everything touching it runs on the vehicle's single-threaded dispatcher. */
    internal val autopilot = SimAutopilot(
        config.autopilot, config.type, config.systemId, config.bootLocation, config.initialCharge, missionServer,
        readyAfter = config.positionReadyAfter.toDouble(DurationUnit.SECONDS),
        sensorsReadyAfter = config.sensorsReadyAfter.toDouble(DurationUnit.SECONDS),
        navigationReadyAfter = config.navigationReadyAfter.toDouble(DurationUnit.SECONDS),
        world = SimWorld(config.bootLocation.altitude.meters, config.terrain, config.objects, config.cameraFov, config.camera),
    )
    private val _photos = MutableStateFlow<List<PhotoEvent>>(emptyList())
    private val _reached = MutableStateFlow<List<Int>>(emptyList())
    private val _texts = MutableSharedFlow<String>(replay = 64, extraBufferCapacity = 64, onBufferOverflow = BufferOverflow.DROP_OLDEST)

    init {
        for ((name, value) in config.parameters) {
            require(autopilot.params.valueOf(name) != null) { "parameters: ${config.autopilot} ${config.type} has no parameter $name" }
            autopilot.params.set(name, value)
        }
        _state = MutableStateFlow(autopilot.state())
    }

    /** HEARTBEAT and the telemetry streams, from the configured (by default the firmware's) rates. */
    private val streams = StreamScheduler(
        config.streamRates, config.timeScale,
        heartbeat = { messages.heartbeat(autopilot.state()) },
        build = { id -> messages.build(id, autopilot.state()) },
        canBuild = messages::canBuild,
        send = ::send,
    )

    /** Photos the simulated camera took, oldest first. */
    public val photos: StateFlow<List<PhotoEvent>> = _photos.asStateFlow()

    /** Sequence numbers of the mission items reached (MISSION_ITEM_REACHED), in order, since boot. */
    public val reachedItems: StateFlow<List<Int>> = _reached.asStateFlow()

    /** STATUSTEXT lines the vehicle sent (the last 64 are replayed to new collectors). */
    public val statusTexts: SharedFlow<String> = _texts.asSharedFlow()
    private var link: MavlinkLink? = null

    /**
     * Simulated time since the vehicle was made: the clock its flight, battery and message rates
     * follow (it stands still while the vehicle is stopped).
     */
    public val clock: Duration get() = simulatedSeconds.seconds

    @Volatile private var simulatedSeconds = 0.0

    /** The simulated state, updated after every physics tick and every handled message while running. */
    public val state: StateFlow<SimState> = _state.asStateFlow()

    /** Message id → rate in Hz of what it streams now, as configured or as a ground station asked. */
    public val streamRates: StateFlow<Map<Int, Double>> = streams.rates

    /** The emulated radio pair its link runs through ([SimVehicleConfig.radio]) while running, or null. */
    public val radioLink: RadioLink? get() = link as? RadioLink

    /** The local UDP port the vehicle sends from, or null when stopped. */
    public val localPort: Int? get() = link?.localPort

    /** Frames it dropped for a missing or bad signature or a stale timestamp, once it holds a signing key. */
    public val refusedFrames: Long get() = signing.refused

    /** Whether the vehicle is running. */
    public val isRunning: Boolean get() = scope != null

    /**
     * Opens the vehicle's socket and starts its loops as children of [parent]. Throws the link's
     * typed errors for a bad [SimVehicleConfig.gcs].
     */
    @OptIn(ExperimentalCoroutinesApi::class)
    public suspend fun start(parent: CoroutineScope) {
        check(scope == null) { "vehicle ${config.systemId} is already running" }
        val link = openLink.open(LinkAddress.parse(config.gcs)).let { l -> config.radio?.let { RadioLink(l, it, timebase) } ?: l }
        val scope = CoroutineScope(
            parent.coroutineContext + SupervisorJob(parent.coroutineContext.job) +
                timebase.dispatcher.limitedParallelism(1) + CoroutineName("sim-${config.systemId}"),
        )
        this.link = link
        this.scope = scope
        missions = scope.serve(VehicleMissions(autopilot), bootedAt) { reply, to -> send(MissionFrames.write(reply, to)) }
        scope.launch { receive(link) }
        scope.launch { physics() }
        streams.start(scope)
    }

    /** Stops sending and closes the socket; the ground station will see the vehicle fall silent. */
    public fun stop() {
        scope?.cancel()
        link?.close()
        scope = null
        link = null
        missions = null
        streams.stop()
    }

    /**
     * Integrates at a fixed simulated step: each tick runs as many steps as the [timebase] time
     * elapsed × [SimVehicleConfig.timeScale] calls for, at most [MAX_STEPS_PER_TICK] (a stalled
     * machine drops simulated time rather than freezing in a catch-up loop).
     */
    private suspend fun physics() {
        val step = config.physicsStep.toDouble(DurationUnit.SECONDS)
        var last = timebase.clock.markNow()
        var owed = 0.0
        while (true) {
            delay(TICK)
            val now = timebase.clock.markNow()
            owed += (now - last).toDouble(DurationUnit.SECONDS) * config.timeScale
            last = now
            var steps = 0
            while (owed >= step && steps < MAX_STEPS_PER_TICK) {
                autopilot.step(step)
                owed -= step
                steps++
            }
            if (steps == MAX_STEPS_PER_TICK) owed = 0.0
            flush()
        }
    }

    /** Sends what the autopilot queued and publishes its state. */
    private suspend fun flush() {
        val outputs = autopilot.drain()
        val s = autopilot.state()
        _state.value = s
        simulatedSeconds = autopilot.time
        for (out in outputs) {
            when (out) {
                is SimOutput.Photo -> _photos.value = _photos.value + out.photo
                is SimOutput.ItemReached -> _reached.value = _reached.value + out.seq
                is SimOutput.Text -> _texts.tryEmit(out.text)
                else -> Unit
            }
            for (message in messages.outputs(out, s, autopilot.params)) send(message)
        }
    }

    private suspend fun receive(link: MavlinkLink) = coroutineScope {
        val decoder = FrameDecoder(codec)
        // The link hands bytes over synchronously; replies need to suspend, so they go through an inbox.
        val inbox = Channel<Pair<MavFrame, Any>>(capacity = 1024, onBufferOverflow = BufferOverflow.DROP_OLDEST)
        launch { for ((frame, message) in inbox) handle(frame, message) }
        link.receive { _, bytes ->
            decoder.feed(bytes) { frame -> if (signing.admits(frame)) codec.decode(frame)?.let { inbox.trySend(frame to it) } }
        }
        inbox.close()
    }

    @Suppress("DEPRECATION") // SET_MODE is deprecated but ground stations still send it
    internal suspend fun handle(frame: MavFrame, message: Any) {
        val mission = MissionFrames.read(message, config.systemId)
        if (mission != null) {
            missions?.receive(mission, Asker(frame.systemId, frame.componentId))
            flush()
            return
        }
        when (message) {
            is CommandLong -> if (addressedToUs(message.targetSystem(), message.targetComponent())) {
                command(
                    CommandRequest(
                        message.command().value(), message.param1(), message.param2(), message.param3(), message.param4(),
                        message.param5().toDouble(), message.param6().toDouble(), message.param7(),
                        frame = null, confirmation = message.confirmation(), sourceSystem = frame.systemId, sourceComponent = frame.componentId,
                    ),
                )
            }
            is CommandInt -> if (addressedToUs(message.targetSystem(), message.targetComponent())) {
                command(
                    CommandRequest(
                        message.command().value(), message.param1(), message.param2(), message.param3(), message.param4(),
                        message.x().toDouble(), message.y().toDouble(), message.z(),
                        frame = message.frame().value(), sourceSystem = frame.systemId, sourceComponent = frame.componentId,
                    ),
                )
            }
            is SetMode -> if (message.targetSystem() == 0 || message.targetSystem() == config.systemId) {
                autopilot.commands.handleSetMode(message.baseMode().value(), message.customMode(), frame.systemId, frame.componentId)
            }
            is ParamRequestRead -> if (addressedToUs(message.targetSystem(), message.targetComponent())) {
                autopilot.paramResponder.read(message.paramId(), message.paramIndex())
            }
            is SetupSigning -> if (addressedToUs(message.targetSystem(), message.targetComponent())) {
                signing.setup(message, autopilot.state().armed)?.let { autopilot.emit(SimOutput.Text(Severity.WARNING, it)) }
            }
            is ParamRequestList -> if (addressedToUs(message.targetSystem(), message.targetComponent())) autopilot.paramResponder.list()
            is ParamSet -> if (addressedToUs(message.targetSystem(), message.targetComponent())) {
                autopilot.paramResponder.set(message.paramId(), message.paramValue())
            }
            else -> return
        }
        flush()
    }

    /** Message-level commands are answered here; everything else is the autopilot's. */
    private suspend fun command(cmd: CommandRequest) {
        val result = when (cmd.command) {
            SET_MESSAGE_INTERVAL -> streams.setInterval(cmd.param1.toInt(), cmd.param2)
            REQUEST_MESSAGE -> requestMessage(cmd.param1.toInt())
            else -> return autopilot.commands.handle(cmd)
        }
        autopilot.emit(SimOutput.Ack(cmd.command, result, 0, cmd.sourceSystem, cmd.sourceComponent))
    }

    private suspend fun requestMessage(messageId: Int): CommandResult {
        val message = messages.build(messageId, autopilot.state()) ?: return CommandResult.DENIED
        send(message)
        return CommandResult.ACCEPTED
    }

    private fun addressedToUs(system: Int, component: Int): Boolean =
        (system == 0 || system == config.systemId) && (component == 0 || component == config.componentId)

    private suspend fun send(message: Any) {
        val link = link ?: return
        link.sendToAll(signing.sign(encoder.encode(message)))
    }

    internal companion object {
        val TICK = 20.milliseconds
        const val MAX_STEPS_PER_TICK = 2000
    }
}
