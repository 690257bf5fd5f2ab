package pod.mavlink.tlog

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.copterHeartbeat
import pod.mavlink.link.MemoryNetwork
import pod.mavlink.virtualTimebase
import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

class StationRecordingTest : StringSpec({

    "a station records every frame it receives and sends, byte for byte, stamped on its clock, until stopped" {
        runTest {
            val timebase = virtualTimebase()
            val network = MemoryNetwork(backgroundScope, timebase)
            val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = timebase)
            val gcs = GroundStation.open(network.open("udpin://127.0.0.1:14550"), backgroundScope, config)
            val vehicleLink = network.open("udpout://127.0.0.1:14550")
            val heardFromGcs = ArrayList<Pair<Long, ByteArray>>()
            val start = 1_700_000_000_000_000L
            val startedAt = testScheduler.currentTime
            backgroundScope.launch {
                vehicleLink.receive { _, bytes -> synchronized(heardFromGcs) { heardFromGcs += (testScheduler.currentTime - startedAt) to bytes } }
            }
            val out = ByteArrayOutputStream()
            val writer = TlogWriter(out)
            val recording = gcs.record(writer, startEpochMicros = start)
            val sentByVehicle = ArrayList<Pair<Long, ByteArray>>()
            val random = Random(11)
            // Heartbeats, and frames of a message id Pod does not know (their checksum cannot be
            // recomputed: they must be recorded as they came), two in one datagram.
            repeat(5) { i ->
                val unknown = FrameEncoder().encode(MavFrame(2, i, 7, 1, 0x812345, random.nextBytes(20)))
                // The checksum a dialect that knows the id would compute (its CRC_EXTRA is not 0, which
                // Pod's encoder assumes for unknown ids): only the bytes as received can give it back.
                unknown[unknown.size - 2] = (unknown[unknown.size - 2] + 1 + i).toByte()
                val frames = listOf(copterHeartbeat(7, i), unknown)
                vehicleLink.sendToAll(frames[0] + frames[1])
                frames.forEach { sentByVehicle += (testScheduler.currentTime - startedAt) to it }
                delay(700.milliseconds)
            }
            delay(1.seconds)
            recording.stop()
            val stoppedAfter = synchronized(heardFromGcs) { heardFromGcs.size }
            writer.close()
            delay(3.seconds) // the station goes on sending; none of it is recorded now

            val records = TlogReader(ByteArrayInputStream(out.toByteArray())).readAll()
            val received = records.filter { it.frame[5].toInt() == 7 }
            val sent = records.filter { it.frame[5].toInt() and 0xFF == 255 }
            (received.size + sent.size) shouldBe records.size
            received.map { it.frame.toList() } shouldBe sentByVehicle.map { it.second.toList() }
            received.map { it.timestampMicros } shouldBe sentByVehicle.map { start + it.first * 1000 }
            sent.map { it.frame.toList() } shouldBe heardFromGcs.take(stoppedAfter).map { it.second.toList() }
            sent.map { it.timestampMicros } shouldBe heardFromGcs.take(stoppedAfter).map { start + it.first * 1000 }
            (sent.size >= 4) shouldBe true // one heartbeat a second for 4.5 s
            (heardFromGcs.size > stoppedAfter) shouldBe true
            gcs.stats.value.recordingErrors shouldBe 0
        }
    }

    "a tap that throws is counted and the station goes on" {
        runTest {
            val timebase = virtualTimebase()
            val network = MemoryNetwork(backgroundScope, timebase)
            val config = GroundStationConfig(streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = timebase)
            val gcs = GroundStation.open(network.open("udpin://127.0.0.1:14550"), backgroundScope, config)
            val vehicleLink = network.open("udpout://127.0.0.1:14550")
            gcs.record(FrameTap { _, _, _ -> error("broken tap") })
            vehicleLink.sendToAll(copterHeartbeat(7, 0))
            gcs.vehicles.first { 7 in it }
            delay(2.seconds)
            (gcs.stats.value.recordingErrors >= 2) shouldBe true
        }
    }
})
