package pod.e2e

import com.github.ajalt.clikt.core.parse
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import pod.cli.Pod
import pod.mavlink.GroundStation
import pod.mavlink.codec.FrameDecoder
import pod.mavlink.codec.MavFrame
import pod.mavlink.tlog.TlogReader
import pod.mavlink.tlog.TlogRecord
import pod.mavlink.tlog.TlogWriter
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration.Companion.seconds

/** What pymavlink and Pod both say of one tlog record. */
private data class Seen(val messageId: Int, val sequence: Int, val systemId: Int, val componentId: Int, val timestampMicros: Long)

private fun TlogRecord.seen(): Seen {
    var frame: MavFrame? = null
    FrameDecoder().feed(this.frame) { frame = it }
    val f = frame ?: throw AssertionError("record at $timestampMicros µs is not one valid frame")
    return Seen(f.messageId, f.sequence, f.systemId, f.componentId, timestampMicros)
}

private fun readWithPod(path: Path): List<Seen> = TlogReader.open(path).use { it.readAll() }.map { it.seen() }

/** The same tlog as pymavlink's mavutil reads it (tlog_read.py). */
private suspend fun readWithPymavlink(path: Path): List<Map<String, String>> {
    val peer = Python.startJson("tlog_read.py", path)
    try {
        val end = withTimeout(60.seconds) { peer.await("end") }
        val items = peer.events.replayCache.filter { it["event"] == "item" }
        items.size shouldBe end.getValue("count").toInt()
        return items
    } finally {
        peer.stop()
    }
}

class TlogInteropSpec : StringSpec({

    "pymavlink reads the tlog a station recorded from a simulated vehicle: the same frames in the same order with the same timestamps" {
        val path = Files.createTempFile("pod", ".tlog")
        try {
            val before = TlogWriter.wallClockMicros()
            coroutineScope {
                val gcs = GroundStation.open("udpin://127.0.0.1:0", this)
                val writer = TlogWriter.create(path)
                val recording = gcs.record(writer)
                val sim = SimVehicle(SimVehicleConfig(systemId = 31, gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
                try {
                    sim.start(this)
                    val vehicle = withTimeout(10.seconds) { gcs.vehicles.first { 31 in it } }.getValue(31)
                    withTimeout(10.seconds) { vehicle.telemetry.position.filterNotNull().first() }
                    // A few seconds of the streams the station asked for, both ways.
                    withTimeout(20.seconds) { gcs.stats.first { it.frames >= 150 } }
                } finally {
                    recording.stop()
                    sim.stop()
                    withContext(NonCancellable) { gcs.closeAndAwait() }
                    writer.close()
                }
            }
            val after = TlogWriter.wallClockMicros()
            val pod = readWithPod(path)
            (pod.size > 150) shouldBe true
            pod.map { it.systemId }.toSet() shouldBe setOf(31, 255)
            pod.forEach { (it.timestampMicros in before..after) shouldBe true }

            val python = readWithPymavlink(path)
            python.map { it["type"] }.filter { it == "BAD_DATA" } shouldBe emptyList()
            python.map {
                Seen(it.getValue("id").toInt(), it.getValue("seq").toInt(), it.getValue("sys").toInt(), it.getValue("comp").toInt(), it.getValue("t_us").toLong())
            } shouldBe pod
        } finally {
            Files.deleteIfExists(path)
        }
    }

    "pod watch --record writes a complete tlog of what it sent and heard when the duration ends" {
        val path = Files.createTempFile("pod-watch", ".tlog")
        try {
            val before = TlogWriter.wallClockMicros()
            coroutineScope {
                val out = Captured()
                val watch = async(Dispatchers.IO) {
                    Pod(out).parse(listOf("watch", "--connect", "udpin:127.0.0.1:0", "--duration", "5s", "--record", path.toString()))
                }
                val listening = withTimeout(20.seconds) { out.flow.first { it.startsWith("listening on") } }
                val port = Regex("local port (\\d+)").find(listening)!!.groupValues[1].toInt()
                val sim = SimVehicle(SimVehicleConfig(systemId = 32, gcs = "udpout://127.0.0.1:$port"))
                try {
                    sim.start(this)
                    withTimeout(10.seconds) { out.flow.first { it == "found vehicle 32: quadrotor on ardupilot" } }
                } finally {
                    sim.stop()
                }
                watch.await()
            }
            val after = TlogWriter.wallClockMicros()
            val records = readWithPod(path) // throws if the file ends inside a record
            records.size shouldBeGreaterThan 10
            val heartbeats = records.filter { it.messageId == 0 }.map { it.systemId }.toSet()
            heartbeats shouldContain 32
            heartbeats shouldContain 255
            records.forEach { (it.timestampMicros in before..after) shouldBe true }
        } finally {
            Files.deleteIfExists(path)
        }
    }
})
