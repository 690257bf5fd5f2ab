package pod.bench.command

import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.openjdk.jmh.annotations.Benchmark
import org.openjdk.jmh.annotations.BenchmarkMode
import org.openjdk.jmh.annotations.Level
import org.openjdk.jmh.annotations.Mode
import org.openjdk.jmh.annotations.OutputTimeUnit
import org.openjdk.jmh.annotations.Scope
import org.openjdk.jmh.annotations.Setup
import org.openjdk.jmh.annotations.State
import org.openjdk.jmh.annotations.TearDown
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.command.CommandReply
import pod.mavlink.command.CommandResult
import pod.mavlink.command.CommandWire
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import java.net.InetSocketAddress
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.seconds

/**
 * What a command exchange costs Pod itself, without the wire: [command] is one
 * `vehicle.commands.send` from `runBlocking` (as a script calls it) to a vehicle whose link
 * answers COMMAND_LONG with an ACCEPTED COMMAND_ACK in place, inside the station's send. So every
 * step of Pod's round trip runs (lock, machine, encode, the in-place driver's taps, decode of the
 * ack, routing, the outcome) but no socket, no other thread and no wake-up: the figure is the
 * CPU time the command round trip benchmark's "caller → link" and "ack out of link → caller"
 * parts hold apart from waiting. Run with `-prof gc` for the bytes allocated per command.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
open class CommandExchangeBenchmark {
    private lateinit var scope: CoroutineScope
    private lateinit var station: GroundStation
    private lateinit var vehicle: MavlinkVehicle

    @Setup(Level.Trial)
    fun setup() {
        scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
        val link = AnsweringLink()
        // One heartbeat only: the vehicle must stay connected for the whole trial.
        val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, lostAfter = 1.hours)
        station = GroundStation.open(link, scope, config)
        link.heartbeat()
        vehicle = runBlocking { withTimeout(5.seconds) { station.vehicles.first { 1 in it } }.getValue(1) }
        val reply = command()
        check(reply.result == CommandResult.ACCEPTED && reply.command == BENCH_COMMAND.command) { "the vehicle answered $reply" }
    }

    @TearDown(Level.Trial)
    fun tearDown() {
        station.close()
        scope.cancel()
    }

    @Benchmark
    fun command(): CommandReply = runBlocking { vehicle.commands.send(BENCH_COMMAND) }
}

/**
 * A link to one vehicle (system 1, component 1) that answers every COMMAND_LONG in place, inside
 * the send, with an ACCEPTED COMMAND_ACK for its command; what else the station sends is dropped.
 */
private class AnsweringLink : MavlinkLink {
    private val encoder = FrameEncoder()
    private val vehicle = LinkPeer(InetSocketAddress("127.0.0.1", 14555))
    private val started = CountDownLatch(1)
    private val stopped = CountDownLatch(1)
    @Volatile private var onBytes: ((LinkPeer, ByteArray) -> Unit)? = null
    private var sequence = 0
    private val acks = HashMap<Int, Array<ByteArray>>()

    override val address: LinkAddress = LinkAddress.parse("udpin://127.0.0.1:0")
    override val localPort: Int = 0
    override val peers: Collection<LinkPeer> = listOf(vehicle)
    override val sendsInPlace: Boolean get() = true

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        this.onBytes = onBytes
        started.countDown()
        kotlinx.coroutines.runInterruptible(Dispatchers.IO) { stopped.await() }
    }

    /** The vehicle's first heartbeat, once the station listens. */
    fun heartbeat() {
        check(started.await(5, TimeUnit.SECONDS)) { "the station never started receiving" }
        val heartbeat = Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
            .baseMode(EnumValue.create(0)).customMode(0).systemStatus(MavState.MAV_STATE_ACTIVE).mavlinkVersion(3).build()
        deliver(heartbeat)
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) = sendNow(bytes, peer)

    override fun sendNow(bytes: ByteArray, peer: LinkPeer) {
        // MAVLink 2: message id in bytes 7..9; COMMAND_LONG's command is payload bytes 28..29.
        val id = (bytes[7].toInt() and 0xFF) or ((bytes[8].toInt() and 0xFF) shl 8) or ((bytes[9].toInt() and 0xFF) shl 16)
        if (id != COMMAND_LONG) return
        val command = (bytes[10 + 28].toInt() and 0xFF) or ((bytes[10 + 29].toInt() and 0xFF) shl 8)
        // The acks are encoded once per command and sequence number: the vehicle's work is not measured.
        val acks = acks.getOrPut(command) {
            val ack = CommandWire.ack(command, CommandResult.ACCEPTED, bytes[5].toInt() and 0xFF, bytes[6].toInt() and 0xFF)
            Array(256) { encoder.encode(ack, 1, 1, it) }
        }
        onBytes!!.invoke(vehicle, acks[sequence++ and 0xFF])
    }

    private fun deliver(message: Any) {
        onBytes!!.invoke(vehicle, encoder.encode(message, 1, 1, sequence++ and 0xFF))
    }

    override fun close() = stopped.countDown()

    private companion object {
        const val COMMAND_LONG = 76
    }
}
