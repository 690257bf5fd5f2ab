package pod.bench.fleet

import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.options.required
import pod.bench.BenchCommand
import pod.bench.count
import io.dronefleet.mavlink.common.Attitude
import io.dronefleet.mavlink.common.CommandAck
import io.dronefleet.mavlink.common.CommandLong
import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.MavResult
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavModeFlag
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.FrameEncoder
import java.net.InetSocketAddress
import java.net.StandardSocketOptions
import java.nio.ByteBuffer
import java.nio.channels.DatagramChannel
import java.nio.channels.SelectionKey
import java.nio.channels.Selector

/**
 * A lean fleet for the fleet-scale benchmark: vehicles [first]..[first]+[count]-1 in this process,
 * one UDP socket each (so each is its own source address, as real vehicles are), all driven by one
 * thread. Each sends HEARTBEAT at 1 Hz, GLOBAL_POSITION_INT at 10 Hz and ATTITUDE at 5 Hz, its
 * phases spread over the period so the fleet's traffic is even, and answers every COMMAND_LONG
 * with an accepted COMMAND_ACK at once. It runs until its stdin closes (the harness ends).
 *
 * Not an autopilot: its point is the station's load, so it does nothing but talk, and costs the
 * machine as little as it can (one thread, a selector, pre-built messages).
 *
 * `java -cp … pod.bench.fleet.FleetSenderKt --port 14550 --first 1 --count 84`
 */
fun main(args: Array<String>) {
    val (port, first, count) = SenderCommand().parse(args)
    FleetSender(InetSocketAddress("127.0.0.1", port), first, count).run()
}

/** The station's port, the first system id and how many vehicles, from the command line. */
private class SenderCommand : BenchCommand<Triple<Int, Int, Int>>("FleetSenderKt", "Lean vehicles for the fleet-scale benchmark.") {
    private val port by option("--port", help = "the station's UDP port on 127.0.0.1").count(1..65_535).required()
    private val first by option("--first", help = "the first system id").count(1..255).required()
    private val count by option("--count", help = "how many vehicles").count(1..255).required()

    override fun options(): Triple<Int, Int, Int> = Triple(port, first, count)
}

private class FleetSender(private val station: InetSocketAddress, private val first: Int, count: Int) {
    private val encoder = FrameEncoder()
    private val selector = Selector.open()
    private val vehicles = List(count) { i -> SenderVehicle(first + i) }
    private val receiveBuffer = ByteBuffer.allocate(2048)
    private val start = System.nanoTime()

    private inner class SenderVehicle(val systemId: Int) {
        val channel: DatagramChannel = DatagramChannel.open().apply {
            setOption(StandardSocketOptions.SO_RCVBUF, 1 shl 18)
            bind(InetSocketAddress("127.0.0.1", 0))
            configureBlocking(false)
        }
        val decoder = FrameDecoder()
        var sequence = 0
        // Spread each vehicle's phases over the periods so that 250 vehicles do not send in step.
        val phaseMs = (systemId * 37L) % 100 * TICK_MS

        fun send(message: Any) {
            val bytes = encoder.encode(message, systemId, 1, sequence, 2)
            sequence = (sequence + 1) and 0xFF
            channel.send(ByteBuffer.wrap(bytes), station)
        }
    }

    private val heartbeat = Heartbeat.builder()
        .type(MavType.MAV_TYPE_QUADROTOR)
        .autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
        .baseMode(EnumValue.of(MavModeFlag.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED))
        .customMode(0)
        .systemStatus(MavState.MAV_STATE_STANDBY)
        .mavlinkVersion(3)
        .build()

    fun run() {
        for (vehicle in vehicles) vehicle.channel.register(selector, SelectionKey.OP_READ, vehicle)
        println("{\"event\":\"ready\",\"vehicles\":\"${vehicles.size}\"}")
        System.out.flush()
        // The harness closes our stdin when it is done; then we stop.
        val stdinClosed = java.util.concurrent.atomic.AtomicBoolean(false)
        kotlin.concurrent.thread(isDaemon = true) {
            runCatching { while (System.`in`.read() >= 0) Unit }
            stdinClosed.set(true)
            selector.wakeup()
        }
        // A 10 ms tick: every tick sends what is due (position every 10th, attitude every 20th,
        // heartbeat every 100th tick of each vehicle's own phase) and answers commands in between.
        var tick = 0L
        while (!stdinClosed.get()) {
            val now = (System.nanoTime() - start) / 1_000_000
            while (tick * TICK_MS <= now) {
                sendDue(tick * TICK_MS)
                tick++
            }
            val untilNext = tick * TICK_MS - (System.nanoTime() - start) / 1_000_000
            selector.select(untilNext.coerceAtLeast(1))
            val keys = selector.selectedKeys().iterator()
            while (keys.hasNext()) {
                val key = keys.next()
                keys.remove()
                answer(key.attachment() as SenderVehicle)
            }
        }
    }

    private fun sendDue(atMs: Long) {
        for (vehicle in vehicles) {
            val t = atMs + vehicle.phaseMs
            if (t % 100 == 0L) vehicle.send(position(vehicle.systemId, t))
            if (t % 200 == 0L) vehicle.send(attitude(t))
            if (t % 1000 == 0L) vehicle.send(heartbeat)
        }
    }

    private fun answer(vehicle: SenderVehicle) {
        while (true) {
            receiveBuffer.clear()
            vehicle.channel.receive(receiveBuffer) ?: return
            receiveBuffer.flip()
            val bytes = ByteArray(receiveBuffer.remaining()).also { receiveBuffer.get(it) }
            vehicle.decoder.feed(bytes) { frame ->
                if (frame.messageId == COMMAND_LONG_ID) {
                    val command = pod.mavlink.codec.MessageCodec.Default.decode(frame) as? CommandLong ?: return@feed
                    if (command.targetSystem() == vehicle.systemId) {
                        vehicle.send(
                            CommandAck.builder()
                                .command(command.command())
                                .result(MavResult.MAV_RESULT_ACCEPTED)
                                .targetSystem(frame.systemId)
                                .targetComponent(frame.componentId)
                                .build(),
                        )
                    }
                }
            }
        }
    }

    private fun position(systemId: Int, atMs: Long): GlobalPositionInt = GlobalPositionInt.builder()
        .timeBootMs(atMs)
        .lat(473_977_000 + systemId * 100)
        .lon(85_455_000 + (atMs / 100).toInt())
        .alt(500_000)
        .relativeAlt(10_000)
        .vx(100).vy(0).vz(0)
        .hdg(9000)
        .build()

    private fun attitude(atMs: Long): Attitude = Attitude.builder()
        .timeBootMs(atMs)
        .roll(0.01f).pitch(-0.02f).yaw((atMs % 6283) / 1000f)
        .rollspeed(0f).pitchspeed(0f).yawspeed(0f)
        .build()

    companion object {
        const val TICK_MS = 10L
        const val COMMAND_LONG_ID = 76
    }
}
