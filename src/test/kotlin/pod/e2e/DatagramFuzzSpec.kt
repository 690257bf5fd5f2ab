package pod.e2e

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.SysStatus
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.isActive
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import pod.core.vehicle.ConnectionState
import pod.mavlink.GroundStation
import pod.mavlink.codec.FrameEncoder
import pod.sim.SimFleet
import pod.sim.SimVehicleConfig
import java.net.InetSocketAddress
import java.nio.ByteBuffer
import java.nio.channels.DatagramChannel
import java.util.concurrent.locks.LockSupport
import kotlin.random.Random
import kotlin.time.Duration.Companion.seconds

class DatagramFuzzSpec : StringSpec({

    "100k random and mutated datagrams at the ground-station port: nothing escapes, telemetry keeps flowing, bad frames are counted" {
        coroutineScope {
            val gcs = GroundStation.open("udpin://127.0.0.1:0", this)
            val fleet = SimFleet.start(3, this, SimVehicleConfig(systemId = 1, gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
            try {
                withTimeout(10.seconds) { gcs.awaitFleetWithPositions(3) }

                val sent = withContext(Dispatchers.IO) { throwDatagrams(gcs.link.localPort, count = 100_000, seed = 20261122) }
                sent shouldBe 100_000

                // After the barrage every vehicle's telemetry still arrives: its received-frame count moves on.
                val before = gcs.vehicles.value.mapValues { it.value.telemetry.linkQuality.value.received }
                withTimeout(10.seconds) {
                    for ((id, count) in before) {
                        gcs.vehicles.value.getValue(id).telemetry.linkQuality.first { it.received > count + 5 }
                    }
                }
                gcs.vehicles.value.values.forEach { it.connection.value shouldBe ConnectionState.CONNECTED }
                gcs.linkError.value.shouldBeNull()
                isActive shouldBe true

                val stats = withTimeout(5.seconds) { gcs.stats.first { it.badCrc > 0 && it.skippedBytes > 0 } }
                stats.badCrc shouldBeGreaterThan 1_000
                stats.skippedBytes shouldBeGreaterThan 100_000
                gcs.vehicles.value.keys shouldBe setOf(1, 2, 3) // garbage never invents a vehicle
            } finally {
                fleet.stop()
                gcs.close()
            }
        }
    }
})

/**
 * Sends [count] datagrams to 127.0.0.1:[port]: a third random bytes, the rest real frames of
 * systems 1..3 with bytes flipped, cut short, doubled or wrapped in garbage. Paced in small bursts
 * so the receiver's buffer is not simply overrun. Returns how many were sent.
 */
private fun throwDatagrams(port: Int, count: Int, seed: Int): Int {
    val random = Random(seed)
    val encoder = FrameEncoder()
    val heartbeat = Heartbeat.builder().type(MavType.MAV_TYPE_QUADROTOR).autopilot(MavAutopilot.MAV_AUTOPILOT_ARDUPILOTMEGA)
        .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_STANDBY).mavlinkVersion(3).build()
    val position = GlobalPositionInt.builder().lat(411780460).lon(-85957860).alt(120000).build()
    val status = SysStatus.builder().voltageBattery(16000).batteryRemaining(80).build()
    val templates = listOf(heartbeat, position, status).flatMap { m ->
        (1..3).flatMap { sys -> listOf(1, 2).map { v -> encoder.encode(m, sys, 1, random.nextInt(256), version = v) } }
    }
    val target = InetSocketAddress("127.0.0.1", port)
    DatagramChannel.open().use { channel ->
        var sent = 0
        val buffer = ByteBuffer.allocate(1024)
        while (sent < count) {
            val bytes = when (random.nextInt(6)) {
                0, 1 -> random.nextBytes(1 + random.nextInt(300))
                2 -> templates.random(random).copyOf().also { f -> repeat(1 + random.nextInt(3)) { f[random.nextInt(f.size)] = random.nextInt(256).toByte() } }
                3 -> templates.random(random).let { f -> f.copyOf(1 + random.nextInt(f.size - 1)) }
                4 -> random.nextBytes(random.nextInt(40)) + templates.random(random).copyOf().also { it[it.size - 1] = (it[it.size - 1] + 1).toByte() } +
                    random.nextBytes(random.nextInt(40))
                else -> byteArrayOf(0xFD.toByte(), 0xFE.toByte()) + templates.random(random).copyOf().also { it[3 + random.nextInt(3)] = random.nextInt(256).toByte() }
            }
            buffer.clear()
            buffer.put(bytes)
            buffer.flip()
            channel.send(buffer, target)
            sent++
            if (sent % 100 == 0) LockSupport.parkNanos(2_000_000) // pacing: ~50k datagrams/s at most
        }
        return sent
    }
}
