package pod.mavlink

import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.isActive
import kotlinx.coroutines.job
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.FrameView
import pod.mavlink.codec.FrameViewSink
import pod.mavlink.codec.MavFrame
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.LinkException
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import pod.mavlink.signing.SignedFrames
import pod.mavlink.telemetry.HotMessages
import pod.mavlink.radio.RadioPacer
import pod.mavlink.radio.RadioStatus
import pod.mavlink.tlog.FrameDirection
import pod.mavlink.tlog.FrameTap
import pod.mavlink.tlog.FrameTaps
import pod.mavlink.tlog.Recording
import pod.mavlink.tlog.TlogWriter
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * One ground station on one link: it parses and routes every frame, sends our HEARTBEAT, finds
 * vehicles by theirs and marks them lost when they fall silent.
 *
 * All its coroutines are children of the scope it was opened in; [close] (or cancelling that scope)
 * stops them and closes the link.
 *
 * ```
 * val gcs = GroundStation.open("udpin://0.0.0.0:14550", scope)
 * val first = gcs.vehicles.first { it.isNotEmpty() }.values.first()
 * first.telemetry.position.filterNotNull().first()
 * ```
 */
public class GroundStation private constructor(
    /** The link this station talks over. */
    public val link: MavlinkLink,
    /** Identity and timing. */
    public val config: GroundStationConfig,
    parent: CoroutineScope,
    private val codec: MessageCodec,
) {
    internal val scope: CoroutineScope = CoroutineScope(
        parent.coroutineContext + SupervisorJob(parent.coroutineContext.job) +
            config.timebase.dispatcher + CoroutineName("pod-gcs(${link.address})"),
    )
    private val encoder = FrameEncoder(codec)
    private val decoders = PeerDecoders(config.maxPeers, codec)
    private val signing = config.signing?.let { SignedFrames(it, codec) }
    private val _stats = MutableStateFlow(LinkStats())
    private val _linkError = MutableStateFlow<LinkException?>(null)
    @Volatile private var fromSystemZero = 0L
    @Volatile private var handlerErrors = 0L
    @Volatile private var trackingErrors = 0L
    private val taps = FrameTaps(config.clock)
    private val forwarding = pod.mavlink.route.StationForwarding(link, codec)
    private val pacer = RadioPacer(config.radioPacing, config.clock)
    private val sender = StationSender(link, config, encoder, signing, pacer, taps)
    private val registry = VehicleRegistry(this, config.lostAfter, StreamRequests(scope, config, ::linkBroken)) { guarded(it) }

    /** Vehicles heard so far by system id, lost ones included (see [MavlinkVehicle.connection]). */
    public val vehicles: StateFlow<Map<Int, MavlinkVehicle>> = registry.vehicles

    /** Found, lost and regained vehicles, as they happen. */
    public val events: SharedFlow<FleetEvent> = registry.events

    /** What the receive path has counted, refreshed about four times a second. */
    public val stats: StateFlow<LinkStats> = _stats.asStateFlow()

    /** The latest RADIO_STATUS a telemetry radio injected, with its source ids; null until one is heard. Sends are paced from it (see [GroundStationConfig.radioPacing]). */
    public val radio: StateFlow<RadioStatus?> = pacer.status

    /** Set when the link broke (a TCP server hung up); the station then hears nothing more. */
    public val linkError: StateFlow<LinkException?> = _linkError.asStateFlow()

    private fun start() {
        scope.launch(CoroutineName("receive")) {
            try {
                link.receive(::onBytes)
            } catch (e: LinkException) {
                _linkError.value = e // the receive side's account is the one that stands
            }
        }
        scope.launch(CoroutineName("heartbeat")) {
            while (isActive) {
                try {
                    sender.send(gcsHeartbeat(), peer = null, paced = false)
                } catch (e: LinkException) {
                    linkBroken(e) // a TCP peer hung up; the receive side reports it too
                }
                delay(config.heartbeatInterval)
            }
        }
        scope.launch(CoroutineName("connection-tracking")) {
            val tick = config.silenceCheckEvery ?: minOf(config.lostAfter / 4, 250.milliseconds)
            while (isActive) {
                delay(tick)
                // Each in its own guard: whatever goes wrong in one pass (stats of a decoder in use,
                // a collector that throws) must not end the loop that marks vehicles lost.
                guarded { registry.checkSilence() }
                guarded { publishStats() }
            }
        }
    }

    /** A send found the link broken: recorded unless the receive side already said how. */
    private fun linkBroken(e: LinkException) {
        _linkError.compareAndSet(null, e)
    }

    /** The shortest resend timeout the link allows now: a paced radio's few frame times, else 0. */
    internal val resendFloorNanos: Long get() = pacer.resendFloorNanos()

    /** How many source addresses have a frame decoder now (at most [GroundStationConfig.maxPeers]). */
    internal val peerCount: Int get() = decoders.size

    /** Sends [message] to [vehicle] (to the address it was heard from, when listening). */
    public suspend fun sendTo(vehicle: MavlinkVehicle, message: Any) {
        sender.send(message, vehicle.peer)
    }

    /**
     * Sends [message] to [vehicle] from the calling thread without suspending, when the link
     * [sends in place][MavlinkLink.sendsInPlace] and the vehicle's address is known; false (and
     * nothing sent) otherwise.
     */
    internal fun sendNow(vehicle: MavlinkVehicle, message: Any): Boolean {
        val peer = vehicle.peer
        if (!sender.canSendNow || peer == null) return false
        sender.sendNow(message, peer)
        return true
    }

    /**
     * Sends [message] where its target_system says: to that vehicle's address when it is known,
     * to every peer when the target is 0 (broadcast), unknown, or the message has no target field.
     */
    public suspend fun send(message: Any) {
        val target = MessageTargets.targetSystem(message)
        val vehicle = if (target == null || target == 0) null else vehicles.value[target]
        if (vehicle != null) sendTo(vehicle, message) else broadcast(message)
    }

    /** Sends [message] to every peer of the link. */
    public suspend fun broadcast(message: Any) {
        sender.send(message, peer = null)
    }

    /**
     * Serves this station's vehicles to another ground station (QGroundControl, MAVProxy) on
     * [other] too: every frame heard here goes there as it came, and what comes back is routed to
     * the vehicles, by mavlink-router's rules ([pod.mavlink.route.MavlinkRouter]). Close the
     * returned router to stop (it closes [other]); closing the station stops it as well.
     */
    public fun forwardTo(other: MavlinkLink): pod.mavlink.route.MavlinkRouter =
        forwarding.start(other, scope, pod.mavlink.route.RouterConfig(timebase = config.timebase))

    /** Opens [connection] (as [GroundStation.open] takes it) and [forwardTo]s it. */
    public suspend fun forwardTo(connection: String): pod.mavlink.route.MavlinkRouter = forwardTo(MavlinkLink.open(connection))

    /** Stops every coroutine of this station and closes its link. */
    public fun close() {
        scope.cancel()
        link.close()
    }

    /**
     * [close]s and suspends until the link's socket is released, at most [within]: its port can
     * then be bound again at once, as by the next command on the same `udpin` port.
     */
    public suspend fun closeAndAwait(within: Duration = 2.seconds) {
        close()
        withTimeoutOrNull(within) { link.awaitClosed() }
    }

    /**
     * Passes every frame this station sends and receives from now on to [tap], until the returned
     * [Recording] is stopped (or the station closed). Frames are stamped in microseconds since the
     * Unix epoch: [startEpochMicros] (the wall clock by default) plus the time elapsed since this
     * call on the station's clock ([GroundStationConfig.timebase]), so the stamps never go back
     * and a virtual-time test gets exact ones. Received frames are stamped when parsed, sent ones
     * when encoded, just before they go out.
     *
     * @see record for a tlog
     */
    public fun record(tap: FrameTap, startEpochMicros: Long = TlogWriter.wallClockMicros()): Recording = taps.add(tap, startEpochMicros)

    /**
     * Writes every frame this station sends and receives from now on to [writer], the tlog that
     * MAVProxy and pymavlink read, until the returned [Recording] is stopped; close [writer] after
     * stopping. Write failures are counted in [LinkStats.recordingErrors].
     */
    public fun record(writer: TlogWriter, startEpochMicros: Long = TlogWriter.wallClockMicros()): Recording =
        record(FrameTap { t, _, frame -> writer.write(t, frame) }, startEpochMicros)

    private inline fun guarded(block: () -> Unit) {
        try {
            block()
        } catch (e: kotlinx.coroutines.CancellationException) {
            throw e
        } catch (e: Exception) {
            trackingErrors++
        }
    }

    // Runs on the link's receive path (a UDP link's own thread), one datagram at a time: it is the
    // only writer of the routing state. What other threads read is safe as follows: `decoders`
    // locks itself (the tracking loop adds up its counters); the registry's `_vehicles`, `_identity`, telemetry
    // and `_payloads` are StateFlows with this one writer (position, attitude, battery, hud and link
    // quality are SnapshotStateFlows: numbers written and read under each one's lock); the registry's
    // `bySystem`, the hot-message holders and the decoders' frame views are this path's alone;
    // `_connection` changes only by compareAndSet (the tracking loop marks LOST, this path CONNECTED
    // again); `peer` and the heartbeat time are @Volatile; `heardMessages` is a concurrent set (StreamRequests clears
    // it); the counters are @Volatile with this one writer; the StatusText joiner is synchronized;
    // events and messages go out through SharedFlow.tryEmit, which is thread-safe.
    private fun onBytes(peer: LinkPeer, bytes: ByteArray) {
        receivingFrom = peer
        decoders.decoderFor(peer).feedViews(bytes, 0, bytes.size, frameSink)
    }

    /** The peer of the datagram being parsed: [frameSink] is made once, so it cannot capture it. */
    private var receivingFrom: LinkPeer? = null

    private val frameSink = FrameViewSink { view -> onFrameView(receivingFrom!!, view) }

    private fun onFrameView(peer: LinkPeer, view: FrameView) {
        // The common case reads a hot telemetry message in place and allocates nothing. Anything a
        // frame object is needed for (signing, recording, forwarding, other messages) copies it out.
        if (signing == null && !taps.active && !forwarding.active && routeInPlace(peer, view)) return
        val frame = view.toFrame()
        if (signing != null && !signing.admit(frame)) return // refused: counted, never recorded or routed
        if (taps.active) taps.onFrame(FrameDirection.RECEIVED, encoder.wireBytes(frame))
        if (forwarding.active) forwarding.onFrame(peer, frame)
        try {
            route(peer, frame)
        } catch (e: Exception) {
            // A frame that passed its CRC but breaks a handler (a vehicle sending nonsense) must
            // not stop the receive loop; it is counted instead.
            handlerErrors++
        }
    }

    /** Routes a hot telemetry message straight from [view] (see [VehicleRegistry.onHotFrame]); false when [route] must. */
    private fun routeInPlace(peer: LinkPeer, view: FrameView): Boolean {
        if (!HotMessages.isHot(view.messageId)) return false
        if (view.systemId == config.systemId && view.componentId == config.componentId) return true
        if (view.systemId == 0) {
            fromSystemZero++
            return true
        }
        return try {
            registry.onHotFrame(peer, view)
        } catch (e: Exception) {
            handlerErrors++ // as in onFrameView: a collector of the telemetry that throws
            true
        }
    }

    private fun route(peer: LinkPeer, frame: MavFrame) {
        if (frame.systemId == config.systemId && frame.componentId == config.componentId) return
        // System id 0 is MAVLink's broadcast address, never a sender's own id ("0 is not a valid
        // vehicle ID", mavlink.io FAQ and serialization guide): such frames are counted, not made a vehicle.
        if (frame.systemId == 0) {
            fromSystemZero++
            return
        }
        val message = codec.decode(frame)
        if (frame.messageId == RadioStatus.MESSAGE_ID) RadioStatus.of(frame, message)?.let(pacer::onReport)
        registry.onMessage(peer, frame, message)
    }

    private fun publishStats() {
        val t = decoders.totals()
        _stats.value = LinkStats(t.frames, t.badCrc, t.skippedBytes, t.unknownMessages, registry.unroutedFrames, handlerErrors, t.evictions, trackingErrors, fromSystemZero, taps.errors)
            .let { if (signing == null) it else signing.countInto(it) }
    }

    private fun gcsHeartbeat(): Heartbeat = Heartbeat.builder()
        .type(MavType.MAV_TYPE_GCS)
        .autopilot(MavAutopilot.MAV_AUTOPILOT_INVALID)
        .baseMode(EnumValue.create(0))
        .customMode(0)
        .systemStatus(MavState.MAV_STATE_ACTIVE)
        .mavlinkVersion(3)
        .build()

    /** Opens ground stations. */
    public companion object {
        /**
         * Opens [connection] (`udpin://0.0.0.0:14550`, `udpout:127.0.0.1:14550`, `tcp://…`) and
         * starts the station in [scope]. Throws the link's typed errors
         * ([pod.mavlink.link.InvalidConnectionString], [pod.mavlink.link.PortInUse],
         * [pod.mavlink.link.HostUnreachable], and for a serial port [pod.mavlink.link.DeviceNotFound]
         * and [pod.mavlink.link.DeviceUnavailable]).
         */
        public suspend fun open(
            connection: String,
            scope: CoroutineScope,
            config: GroundStationConfig = GroundStationConfig(),
            codec: MessageCodec = MessageCodec.Default,
        ): GroundStation = open(MavlinkLink.open(connection), scope, config, codec)

        /** Starts a station on an already open [link] in [scope]. */
        public fun open(
            link: MavlinkLink,
            scope: CoroutineScope,
            config: GroundStationConfig = GroundStationConfig(),
            codec: MessageCodec = MessageCodec.Default,
        ): GroundStation = GroundStation(link, config, scope, codec).also { it.start() }
    }
}
