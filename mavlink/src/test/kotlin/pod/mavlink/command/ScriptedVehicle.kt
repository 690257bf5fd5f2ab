package pod.mavlink.command

import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.util.EnumValue
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.withTimeout
import pod.mavlink.virtualTimebase
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkEnums
import pod.mavlink.MavlinkVehicle
import pod.mavlink.link.MemoryNetwork
import kotlin.time.Duration.Companion.seconds
import pod.mavlink.SequenceNumbers
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.MavlinkLink

/**
 * A vehicle on a link (a loopback socket or a memory network) whose answers a test scripts: for every message the ground
 * station sends it calls [answer] and sends back what that returns (the station's own stream
 * requests only when started with seeStationRequests). Heartbeats go out every 100 ms until
 * [silence] is called.
 */
class ScriptedVehicle private constructor(
    private val link: MavlinkLink,
    private val systemId: Int,
    private val autopilot: Int,
    private val answer: suspend (message: Any) -> List<Any>,
    private val seeStationRequests: Boolean,
) {
    private val encoder = FrameEncoder()
    private val sequences = SequenceNumbers()
    private var heartbeats: Job? = null

    /** COMMAND_LONGs received: command and confirmation. */
    val commands = MutableStateFlow<List<Pair<Int, Int>>>(emptyList())

    private var scope: CoroutineScope? = null

    private fun start(scope: CoroutineScope) {
        this.scope = scope
        beat()
        scope.launch {
            val decoder = FrameDecoder()
            val inbox = kotlinx.coroutines.channels.Channel<Any>(kotlinx.coroutines.channels.Channel.UNLIMITED)
            launch { for (message in inbox) answer(message).forEach { send(it) } }
            link.receive { _, bytes ->
                decoder.feed(bytes) { frame ->
                    val message = MessageCodec.Default.decode(frame) ?: return@feed
                    // What the station asks on its own (stream rates, the home) is not a command under test.
                    val stationRequest = message is CommandLong && (
                        message.command().value() == MavCommands.SET_MESSAGE_INTERVAL ||
                            (message.command().value() == MavCommands.REQUEST_MESSAGE && message.param1() == 242f)
                        )
                    if (stationRequest && !seeStationRequests) return@feed
                    if (message is Heartbeat) return@feed
                    if (message is CommandLong && !stationRequest) commands.update { it + (message.command().value() to message.confirmation()) }
                    inbox.trySend(message)
                }
            }
        }
    }

    private fun beat() {
        val scope = scope ?: return
        heartbeats = scope.launch {
            while (true) {
                send(
                    Heartbeat.builder().type(EnumValue.create(2)).autopilot(EnumValue.create(autopilot))
                        .baseMode(EnumValue.create(1)).systemStatus(MavState.MAV_STATE_STANDBY).mavlinkVersion(3).build(),
                )
                delay(100.milliseconds)
            }
        }
    }

    /** Stops the heartbeats (and nothing else): the ground station will mark the vehicle lost. */
    fun silence() {
        heartbeats?.cancel()
    }

    /** Starts the heartbeats again after [silence]: the ground station will find the vehicle again. */
    fun resume() {
        if (heartbeats?.isActive != true) beat()
    }

    suspend fun send(message: Any) {
        link.sendToAll(encoder.encode(message, systemId, 1, sequences.next(systemId, 1)))
    }

    fun close() = link.close()

    companion object {
        /** Opens a vehicle sending to the ground station at [gcsPort] and starts it in [scope]. */
        suspend fun start(
            scope: CoroutineScope,
            gcsPort: Int,
            systemId: Int = 1,
            autopilot: Int = MavlinkEnums.MAV_AUTOPILOT_ARDUPILOTMEGA,
            seeStationRequests: Boolean = false,
            answer: suspend (message: Any) -> List<Any>,
        ): ScriptedVehicle =
            start(scope, MavlinkLink.open("udpout://127.0.0.1:$gcsPort"), systemId, autopilot, seeStationRequests, answer)

        /** Starts a vehicle on [link] (a socket, or a memory network's) in [scope]. */
        fun start(
            scope: CoroutineScope,
            link: MavlinkLink,
            systemId: Int = 1,
            autopilot: Int = MavlinkEnums.MAV_AUTOPILOT_ARDUPILOTMEGA,
            seeStationRequests: Boolean = false,
            answer: suspend (message: Any) -> List<Any>,
        ): ScriptedVehicle = ScriptedVehicle(link, systemId, autopilot, answer, seeStationRequests).also { it.start(scope) }

        /**
         * Runs [block] in virtual time with a ground station ([config] on the test scheduler's
         * timebase) and one scripted vehicle on a [MemoryNetwork], once the station has heard it:
         * for tests whose subject is timeouts and resends, not the socket.
         */
        fun inVirtualTime(
            config: GroundStationConfig,
            autopilot: Int = MavlinkEnums.MAV_AUTOPILOT_ARDUPILOTMEGA,
            seeStationRequests: Boolean = false,
            answer: suspend (message: Any) -> List<Any>,
            block: suspend CoroutineScope.(MavlinkVehicle, ScriptedVehicle) -> Unit,
        ) = runTest {
            val timebase = virtualTimebase()
            coroutineScope {
                val network = MemoryNetwork(this, timebase)
                val gcs = GroundStation.open(network.open("udpin://127.0.0.1:14550"), this, config.copy(timebase = timebase))
                val vehicle = start(this, network.open("udpout://127.0.0.1:14550"), autopilot = autopilot, seeStationRequests = seeStationRequests, answer = answer)
                try {
                    block(withTimeout(5.seconds) { gcs.vehicles.first { 1 in it } }.getValue(1), vehicle)
                } finally {
                    vehicle.close()
                    gcs.close()
                    coroutineContext[Job]?.children?.forEach { it.cancel() }
                }
            }
        }
    }
}
