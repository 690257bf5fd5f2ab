package pod.mavlink.mission

import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.TestScope
import pod.core.time.Timebase
import pod.mavlink.virtualTimebase
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec
import pod.mavlink.link.LinkConditions
import pod.mavlink.link.MavlinkLink
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.link.TimedDatagram
import pod.mavlink.vehicle.Asker
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.MissionServerFlavor
import pod.mavlink.vehicle.serve
import kotlin.random.Random
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** What goes wrong on one direction of the test link: probabilities, and a delay range in milliseconds. */
internal data class Faults(
    val drop: Double = 0.0,
    val duplicate: Double = 0.0,
    val minDelayMs: Long = 5,
    val maxDelayMs: Long = 5,
    /** Probability that a datagram is held back 50..300 ms, arriving long after later ones. */
    val hold: Double = 0.0,
)

/** [faults] drawn from [random]: loss, duplication, and reordering by delay jitter and hold-backs. */
internal class SeededConditions(
    private val faults: Faults,
    private val random: Random,
    /** Datagrams lost on purpose, whatever the faults say (null: none). */
    private val lose: ((ByteArray) -> Boolean)? = null,
) : LinkConditions {
    override fun offer(bytes: ByteArray, now: Duration): List<TimedDatagram> {
        if (lose?.invoke(bytes) == true) return emptyList()
        if (random.nextDouble() < faults.drop) return emptyList()
        val copies = if (random.nextDouble() < faults.duplicate) 2 else 1
        return List(copies) {
            var delayMs = if (faults.maxDelayMs > faults.minDelayMs) random.nextLong(faults.minDelayMs, faults.maxDelayMs + 1) else faults.minDelayMs
            if (random.nextDouble() < faults.hold) delayMs += random.nextLong(50, 301)
            TimedDatagram(now + delayMs.milliseconds, bytes)
        }
    }

    override val nextRelease: Duration? get() = null

    override fun release(now: Duration): List<TimedDatagram> = emptyList()
}

/**
 * A vehicle on a [MemoryNetwork] whose mission protocol is the real [MissionServer]: it
 * heartbeats as [autopilot] (by default the server's flavour), decodes what the station sends,
 * and [serve]s the server on the test clock (its answers and its re-request timer).
 */
internal class MissionVehicle(
    val server: MissionServer,
    private val link: MavlinkLink,
    private val timebase: Timebase,
    private val autopilot: MavAutopilot = if (server.flavor == MissionServerFlavor.PX4) MavAutopilot.MAV_AUTOPILOT_PX4 else MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA,
) {
    private val encoder = FrameEncoder()
    private val decoder = FrameDecoder()
    private val inbox = Channel<Pair<MissionMessage, Asker>>(Channel.UNLIMITED)
    private val origin = timebase.clock.markNow()
    private var sequence = 0

    /** Nanoseconds on the vehicle's clock, as the server counts them. */
    fun now(): Long = origin.elapsedNow().inWholeNanoseconds

    /** Starts heartbeating, listening and serving, in [scope]. */
    fun start(scope: CoroutineScope) {
        scope.launch {
            link.receive { _, bytes ->
                decoder.feed(bytes) { frame ->
                    val message = MessageCodec.Default.decode(frame) ?: return@feed
                    MissionWire.decode(message)?.let { inbox.trySend(it to Asker(frame.systemId, frame.componentId)) }
                }
            }
        }
        scope.launch {
            while (true) {
                val beat = Heartbeat.builder().type(if (server.fixedWing) MavType.MAV_TYPE_FIXED_WING else MavType.MAV_TYPE_QUADROTOR)
                    .autopilot(autopilot).baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_STANDBY).mavlinkVersion(3).build()
                send(beat)
                delay(1.seconds)
            }
        }
        val serving = scope.serve(server, origin) { answer, to -> send(MissionWire.encode(answer, to.systemId, to.componentId)) }
        scope.launch {
            for ((message, from) in inbox) serving.receive(message, from)
        }
    }

    /**
     * Waits until the vehicle has no transfer going (its timer is off and nothing is on the way to
     * it), at most [limit]; returns whether it got there.
     */
    suspend fun settle(limit: Duration = 60.seconds): Boolean {
        val until = now() + limit.inWholeNanoseconds
        while (now() < until) {
            if (!server.uploading && inbox.isEmpty) {
                delay(1.seconds) // anything still on the way arrives meanwhile
                if (!server.uploading && inbox.isEmpty) return true
            } else {
                delay(100.milliseconds)
            }
        }
        return false
    }

    private suspend fun send(message: Any) {
        link.sendToAll(encoder.encode(message, SYSTEM_ID, 1, sequence++ and 255))
    }

    companion object {
        const val SYSTEM_ID = 1
    }
}

/**
 * A [GroundStation] and a [MissionVehicle] serving [server] on one [MemoryNetwork] under this test's
 * virtual clock, each direction of the link with its faults drawn from [seed]; runs [block] with the
 * station's view of the vehicle. The station never takes the vehicle for lost on a lossy link
 * (what is tested is the transfer, not the heartbeat watch).
 */
internal suspend fun TestScope.onLossyLink(
    server: MissionServer,
    up: Faults,
    down: Faults,
    seed: Long,
    autopilot: MavAutopilot? = null,
    /** Mission messages lost on purpose ([toVehicle]: on the way up), whatever the faults say. */
    lose: ((message: MissionMessage, toVehicle: Boolean) -> Boolean)? = null,
    block: suspend (vehicle: MavlinkVehicle, onBoard: MissionVehicle) -> Unit,
) {
    val timebase = virtualTimebase()
    fun losing(toVehicle: Boolean): ((ByteArray) -> Boolean)? = lose?.let { rule ->
        { bytes -> missionMessagesIn(bytes).any { rule(it, toVehicle) } }
    }
    val network = MemoryNetwork(backgroundScope, timebase) { _, to ->
        if (to.port == STATION_PORT) {
            SeededConditions(down, Random(seed * 31 + 1), losing(toVehicle = false))
        } else {
            SeededConditions(up, Random(seed * 31 + 2), losing(toVehicle = true))
        }
    }
    val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, lostAfter = 24.hours, timebase = timebase)
    val station = GroundStation.open(network.open("udpin://127.0.0.1:$STATION_PORT"), backgroundScope, config)
    val onBoard = if (autopilot == null) {
        MissionVehicle(server, network.open("udpout://127.0.0.1:$STATION_PORT"), timebase)
    } else {
        MissionVehicle(server, network.open("udpout://127.0.0.1:$STATION_PORT"), timebase, autopilot)
    }
    onBoard.start(backgroundScope)
    val vehicle = station.vehicles.first { MissionVehicle.SYSTEM_ID in it }.getValue(MissionVehicle.SYSTEM_ID)
    block(vehicle, onBoard)
}

private const val STATION_PORT = 14550

/** The mission messages in one datagram. */
private fun missionMessagesIn(bytes: ByteArray): List<MissionMessage> {
    val found = ArrayList<MissionMessage>()
    FrameDecoder().feed(bytes) { frame -> MessageCodec.Default.decode(frame)?.let(MissionWire::decode)?.let { found += it } }
    return found
}
