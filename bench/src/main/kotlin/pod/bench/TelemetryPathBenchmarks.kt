package pod.bench

import io.dronefleet.mavlink.common.Attitude
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.common.VfrHud
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.cancel
import org.openjdk.jmh.annotations.Benchmark
import org.openjdk.jmh.annotations.BenchmarkMode
import org.openjdk.jmh.annotations.Mode
import org.openjdk.jmh.annotations.OutputTimeUnit
import org.openjdk.jmh.annotations.Param
import org.openjdk.jmh.annotations.Scope
import org.openjdk.jmh.annotations.Setup
import org.openjdk.jmh.annotations.State
import org.openjdk.jmh.annotations.TearDown
import org.openjdk.jmh.infra.Blackhole
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.mavlink.link.LinkAddress
import pod.mavlink.link.LinkPeer
import pod.mavlink.link.MavlinkLink
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.hours

/**
 * One datagram through a ground station to its vehicle's telemetry, as a UDP link's receive thread
 * hands it over: the station's per-datagram handler (frame sync, CRC, routing by system id,
 * sequence tracking, telemetry) called in place, for each of the five messages a vehicle streams
 * most. Measured with `-prof gc` for the bytes allocated per datagram (gc.alloc.rate.norm).
 *
 * [changing] "no": the same values every frame (a vehicle on the ground); "yes": every frame
 * differs from the one before (a vehicle in flight), so every telemetry value changes. The 256
 * datagrams carry consecutive sequence numbers, as a vehicle sends them. Nobody collects the flows
 * or [MavlinkVehicle.messages]; [feedAndRead] also reads the message's telemetry value each time
 * (a reader as fast as the stream).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
open class TelemetryPathBenchmark {
    @Param("HEARTBEAT", "SYS_STATUS", "ATTITUDE", "GLOBAL_POSITION_INT", "VFR_HUD")
    @JvmField
    var message: String = ""

    @Param("no", "yes")
    @JvmField
    var changing: String = ""

    private lateinit var scope: CoroutineScope
    private lateinit var handler: (LinkPeer, ByteArray) -> Unit
    private lateinit var vehicle: MavlinkVehicle
    private val peer = LinkPeer("vehicle-1")
    private val datagrams = arrayOfNulls<ByteArray>(256)
    private var next = 0

    @Setup
    fun setup() {
        scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
        val link = CapturingLink()
        val config = GroundStationConfig(
            lostAfter = 24.hours, // no vehicle is lost while a benchmark feeds it only one message
            streamRates = emptyMap(),
            requestHome = false,
            requestPayloads = false,
        )
        val station = GroundStation.open(link, scope, config)
        handler = link.awaitHandler()
        handler(peer, Fixtures.mavlink2Datagram(Fixtures.vehicleHeartbeat(), Fixtures.SYSTEM_ID, Fixtures.COMPONENT_ID, 255))
        vehicle = checkNotNull(station.vehicles.value[Fixtures.SYSTEM_ID]) { "the station made no vehicle of the heartbeat" }
        val moving = changing == "yes"
        for (i in datagrams.indices) {
            val variant = if (moving) i else 0
            datagrams[i] = Fixtures.mavlink2Datagram(sample(variant), Fixtures.SYSTEM_ID, Fixtures.COMPONENT_ID, i)
        }
        next = 0
        val before = vehicle.telemetry.linkQuality.value.received
        feed()
        check(vehicle.telemetry.linkQuality.value.received == before + 1) { "the station did not route $message to the vehicle" }
        check(read() != null) { "$message did not reach the vehicle's telemetry" }
    }

    @TearDown
    fun tearDown() {
        scope.cancel()
    }

    @Benchmark
    fun feed() {
        handler(peer, datagrams[next]!!)
        next = (next + 1) and 0xFF
    }

    @Benchmark
    fun feedAndRead(blackhole: Blackhole) {
        feed()
        blackhole.consume(read())
    }

    /** The telemetry value [message] updates. */
    private fun read(): Any? = when (message) {
        "HEARTBEAT" -> vehicle.telemetry.mode.value
        "SYS_STATUS" -> vehicle.telemetry.battery.value
        "ATTITUDE" -> vehicle.telemetry.attitude.value
        "GLOBAL_POSITION_INT" -> vehicle.telemetry.position.value
        else -> vehicle.telemetry.hud.value
    }

    /** The message of this benchmark, its values shifted by [variant] (0: the base values). */
    private fun sample(variant: Int): Any = when (message) {
        "HEARTBEAT" -> Heartbeat.builder()
            .type(MavType.MAV_TYPE_QUADROTOR)
            .autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
            .baseMode(EnumValue.create(if (variant % 2 == 0) 209 else 81)) // armed, disarmed
            .customMode(if (variant % 2 == 0) 4L else 5L) // GUIDED, LOITER
            .systemStatus(MavState.MAV_STATE_ACTIVE)
            .mavlinkVersion(3)
            .build()
        "SYS_STATUS" -> SysStatus.builder()
            .onboardControlSensorsPresent(EnumValue.create(0x3520_FC2F))
            .onboardControlSensorsEnabled(EnumValue.create(0x3520_FC2F))
            .onboardControlSensorsHealth(EnumValue.create(0x3520_FC2F))
            .load(312)
            .voltageBattery(15_840 - variant)
            .currentBattery(1_530)
            .batteryRemaining(78 - variant % 50)
            .build()
        "ATTITUDE" -> Attitude.builder()
            .timeBootMs(1_234_567L + variant * 100L)
            .roll(0.0523f + variant * 0.001f)
            .pitch(-0.0311f)
            .yaw(2.7412f - variant * 0.002f)
            .rollspeed(0.0012f)
            .pitchspeed(-0.0009f)
            .yawspeed(0.1003f)
            .build()
        "GLOBAL_POSITION_INT" -> Fixtures.globalPosition(latitudeE7 = 473_977_418 + variant * 37, timeBootMs = 1_234_567L + variant * 100L)
        "VFR_HUD" -> VfrHud.builder()
            .airspeed(12.5f + variant * 0.01f)
            .groundspeed(11.75f + variant * 0.01f)
            .alt(48.8f)
            .climb(-0.25f)
            .heading(270)
            .throttle(43)
            .build()
        else -> error("no sample for $message")
    }
}

/** A link whose receive hands its per-datagram handler to the benchmark and then waits: the benchmark is the receive thread. */
private class CapturingLink : MavlinkLink {
    override val address: LinkAddress = LinkAddress.UdpIn("127.0.0.1", 0)
    override val localPort: Int = 0
    override val peers: Collection<LinkPeer> = emptyList()

    @Volatile private var handler: ((LinkPeer, ByteArray) -> Unit)? = null

    override suspend fun receive(onBytes: (peer: LinkPeer, bytes: ByteArray) -> Unit) {
        handler = onBytes
        awaitCancellation()
    }

    override suspend fun send(bytes: ByteArray, peer: LinkPeer) {} // the station's own heartbeat: not measured

    override fun close() {}

    /** The handler, once the station's receive coroutine has started (within a few seconds). */
    fun awaitHandler(): (LinkPeer, ByteArray) -> Unit {
        val deadline = System.nanoTime() + 10_000_000_000L
        while (true) {
            handler?.let { return it }
            check(System.nanoTime() < deadline) { "the station never started receiving" }
            Thread.onSpinWait()
        }
    }
}
