package pod.mavlink

import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.MavCmd
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import java.net.InetSocketAddress
import java.nio.ByteBuffer
import java.nio.channels.DatagramChannel
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.withTimeout
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MessageCodec
import pod.mavlink.command.MavCommands

/** A bare UDP "vehicle" for routing tests: sends what it is told, records the commands it receives. */
private class RawVehicle(val systemId: Int, private val gcsPort: Int) : AutoCloseable {
    private val channel = DatagramChannel.open().bind(InetSocketAddress("127.0.0.1", 0))
    private val encoder = FrameEncoder()
    private val decoder = FrameDecoder()
    private val buffer = ByteBuffer.allocate(2048)

    fun heartbeat() {
        val hb = Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
            .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_STANDBY).mavlinkVersion(3).build()
        channel.send(ByteBuffer.wrap(encoder.encode(hb, systemId, 1, 0)), InetSocketAddress("127.0.0.1", gcsPort))
    }

    /** Blocks until a COMMAND_LONG with [command] arrives; returns the test-relevant commands seen up to it. */
    fun commandsUntil(command: Int): List<Int> {
        val seen = ArrayList<Int>()
        while (command !in seen) {
            buffer.clear()
            channel.receive(buffer)
            buffer.flip()
            val bytes = ByteArray(buffer.remaining()).also { buffer.get(it) }
            decoder.feed(bytes) { frame ->
                val message = MessageCodec.Default.decode(frame)
                // The station's own requests on discovery (stream rates, the home) are not under test here.
                val stationRequest = message is CommandLong && (
                    message.command().value() == MavCommands.SET_MESSAGE_INTERVAL ||
                        (message.command().value() == MavCommands.REQUEST_MESSAGE && message.param1() == 242f)
                    )
                if (message is CommandLong && !stationRequest) {
                    seen += message.command().value()
                }
            }
        }
        return seen
    }

    override fun close() = channel.close()
}

class RoutingTest : StringSpec({

    "a message for one vehicle goes only to its address; target 0 goes to every vehicle" {
        coroutineScope {
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this, GroundStationConfig(requestPayloads = false))
            RawVehicle(1, gcs.link.localPort).use { a ->
                RawVehicle(2, gcs.link.localPort).use { b ->
                    try {
                        a.heartbeat()
                        b.heartbeat()
                        withTimeout(5.seconds) { gcs.vehicles.first { it.size == 2 } }
                        fun command(target: Int, cmd: MavCmd) = CommandLong.builder().targetSystem(target).targetComponent(1).command(cmd).build()
                        gcs.send(command(1, MavCmd.MAV_CMD_REQUEST_MESSAGE))
                        gcs.send(command(0, MavCmd.MAV_CMD_DO_SET_MODE))
                        val toA = withTimeout(5.seconds) { runInterruptible(Dispatchers.IO) { a.commandsUntil(176) } }
                        val toB = withTimeout(5.seconds) { runInterruptible(Dispatchers.IO) { b.commandsUntil(176) } }
                        toA shouldBe listOf(512, 176)
                        toB shouldBe listOf(176)
                    } finally {
                        gcs.close()
                    }
                }
            }
        }
    }

    "a heartbeat from system id 0, the broadcast address, is counted in the link stats and never becomes a vehicle" {
        coroutineScope {
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this)
            RawVehicle(0, gcs.link.localPort).use { zero ->
                RawVehicle(7, gcs.link.localPort).use { seven ->
                    try {
                        zero.heartbeat()
                        withTimeout(5.seconds) { gcs.stats.first { it.fromSystemZero >= 1 } }
                        // A real vehicle heard after it shows the link works and routes as before.
                        seven.heartbeat()
                        withTimeout(5.seconds) { gcs.vehicles.first { 7 in it } }
                        gcs.vehicles.value.keys shouldBe setOf(7)
                    } finally {
                        gcs.close()
                    }
                }
            }
        }
    }
})
