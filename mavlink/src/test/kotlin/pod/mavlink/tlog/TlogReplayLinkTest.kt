package pod.mavlink.tlog

import io.dronefleet.mavlink.common.GlobalPositionInt
import io.dronefleet.mavlink.common.HomePosition
import io.dronefleet.mavlink.minimal.Heartbeat
import io.dronefleet.mavlink.minimal.MavAutopilot
import io.dronefleet.mavlink.minimal.MavState
import io.dronefleet.mavlink.minimal.MavType
import io.dronefleet.mavlink.util.EnumValue
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.StringSpec
import io.kotest.engine.spec.tempfile
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.longs.shouldBeInRange
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import io.kotest.property.Arb
import io.kotest.property.arbitrary.double
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.checkAll
import kotlinx.coroutines.flow.filterIsInstance
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.ConnectionState
import pod.mavlink.FleetEvent
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.codec.FrameEncoder
import pod.mavlink.copterHeartbeat
import pod.mavlink.virtualTimebase
import java.io.File
import kotlin.math.roundToInt
import kotlin.time.Duration.Companion.microseconds
import kotlin.time.Duration.Companion.milliseconds

private val encoder = FrameEncoder()
private const val T0 = 1_700_000_000_000_000L
private val origin = Location(47.397742, 8.545594, 488.0.m)

private fun position(at: Location) = GlobalPositionInt.builder()
    .lat((at.latitude * 1e7).roundToInt()).lon((at.longitude * 1e7).roundToInt())
    .alt((at.altitude.meters * 1000).roundToInt()).relativeAlt(0).build()

private fun gcsHeartbeat() = Heartbeat.builder().type(MavType.MAV_TYPE_GCS).autopilot(MavAutopilot.MAV_AUTOPILOT_INVALID)
    .baseMode(EnumValue.create(0)).systemStatus(MavState.MAV_STATE_ACTIVE).mavlinkVersion(3).build()

private fun File.writeTlog(records: List<TlogRecord>): File = apply {
    TlogWriter.create(toPath()).use { w -> records.forEach { w.write(it.timestampMicros, it.frame) } }
}

/**
 * Thirty seconds of two copters: heartbeats at 1 Hz, positions at 4 Hz (vehicle 1 flies 60 m
 * north, vehicle 2 sits), a ground station's heartbeat, vehicle 1's home; vehicle 2 falls silent
 * after 10 s.
 */
private fun twoCopters(): List<TlogRecord> = buildList {
    for (tick in 0 until 120) {
        val t = T0 + tick * 250_000L
        if (tick % 4 == 0) {
            add(TlogRecord(t, copterHeartbeat(1, tick)))
            if (tick < 40) add(TlogRecord(t, copterHeartbeat(2, tick)))
            add(TlogRecord(t, encoder.encode(gcsHeartbeat(), 255, 190, tick and 255)))
        }
        add(TlogRecord(t + 1, encoder.encode(position(origin.offset((tick * 0.5).m, 0.m)), 1, 1, tick and 255)))
        if (tick < 40) add(TlogRecord(t + 2, encoder.encode(position(origin.offset(0.m, 30.m)), 2, 1, tick and 255)))
        if (tick == 8) {
            add(TlogRecord(t + 3, encoder.encode(HomePosition.builder().latitude((origin.latitude * 1e7).roundToInt()).longitude((origin.longitude * 1e7).roundToInt()).altitude(488_000).build(), 1, 1, 0)))
        }
    }
}

class TlogReplayLinkTest : StringSpec({

    "every record is delivered once, in file order, when its log time divided by the speed has passed; a stamp that goes back waits for nothing" {
        checkAll(60, Arb.list(Arb.int(-2_000, 3_000), 1..40), Arb.double(0.25, 400.0, includeNaNs = false)) { steps, speed ->
            // Steps in milliseconds; negative ones are a recorder's clock stepping back.
            var t = T0
            val records = steps.mapIndexed { i, step ->
                t += step * 1000L
                TlogRecord(t, copterHeartbeat(1, i))
            }
            val file = tempfile(suffix = ".tlog").writeTlog(records)
            runTest {
                val link = TlogReplayLink.open(file.toPath(), speed, virtualTimebase())
                val delivered = mutableListOf<Pair<Long, ByteArray>>()
                link.receive { peer, bytes ->
                    peer shouldBe TlogReplayLink.RECORDING
                    delivered += testScheduler.currentTime to bytes
                }
                delivered.map { it.second.toList() } shouldContainExactly records.map { it.frame.toList() }
                val first = records[0].timestampMicros
                var expected = 0.0
                delivered.zip(records).forEach { (at, record) ->
                    expected = maxOf(expected, (record.timestampMicros - first).coerceAtLeast(0) / 1000.0 / speed)
                    // The test scheduler keeps whole milliseconds: a delay is rounded up to one.
                    at.first shouldBeInRange kotlin.math.floor(expected - 1e-9).toLong()..kotlin.math.ceil(expected + 1e-9).toLong() + 1
                }
                link.progress.value shouldBe ReplayProgress(
                    records = records.size.toLong(),
                    logTime = (records.maxOf { it.timestampMicros } - first).coerceAtLeast(0).microseconds,
                    finished = true,
                )
            }
        }
    }

    "a station on a replay shows the logged vehicles as they were, finds them lost when the log falls silent, and tracks what a tlog reader reads" {
        val records = twoCopters()
        val file = tempfile(suffix = ".tlog").writeTlog(records)
        runTest {
            val timebase = virtualTimebase()
            val link = TlogReplayLink.open(file.toPath(), speed = 10.0, timebase = timebase, paused = true)
            val gcs = GroundStation.open(
                link, backgroundScope,
                GroundStationConfig(lostAfter = 300.milliseconds, streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = timebase),
            )
            val tracks = TrackRecorder()
            gcs.record(tracks, startEpochMicros = T0)
            val lost = backgroundScope.launch(timebase.dispatcher) { gcs.events.filterIsInstance<FleetEvent.Lost>().first() }
            link.play()
            link.progress.first { it.finished }
            // The last record is at 29.750001 s of log: at 10x, 2.975 s (a delay rounds up to the next millisecond).
            testScheduler.currentTime shouldBeInRange 2_975L..2_976L
            gcs.vehicles.value.keys shouldBe setOf(1, 2)
            val one = gcs.vehicles.value.getValue(1)
            one.telemetry.position.value!!.location.distanceTo(origin.offset(59.5.m, 0.m)).meters shouldBe (0.0 plusOrMinus 0.02)
            one.telemetry.home.value!!.distanceTo(origin).meters shouldBe (0.0 plusOrMinus 0.02)
            // Vehicle 2's last heartbeat is at 9 s of log: lost 0.3 s (3 s of log) after it.
            lost.isCompleted shouldBe true
            lost.join()
            gcs.vehicles.value.getValue(2).connection.value shouldBe ConnectionState.LOST
            one.connection.value shouldBe ConnectionState.CONNECTED
            link.progress.value.records shouldBe records.size.toLong()
            link.progress.value.error shouldBe null

            val read = TlogTracks.read(file.toPath())
            tracks.tracks().map { it.copy(timesMicros = emptyList()) } shouldBe read.tracks.map { it.copy(timesMicros = emptyList()) }
            tracks.tracks().map { it.systemId } shouldBe listOf(1, 2)
            gcs.close()
        }
    }

    "a log cut inside its last record plays every whole record before the cut, then ends with TlogTruncated" {
        val records = twoCopters().take(50)
        val file = tempfile(suffix = ".tlog").writeTlog(records)
        file.writeBytes(file.readBytes().let { it.copyOf(it.size - 7) })
        runTest {
            val link = TlogReplayLink.open(file.toPath(), speed = 5.0, timebase = virtualTimebase())
            var count = 0
            link.receive { _, _ -> count++ }
            count shouldBe 49
            link.progress.value.finished shouldBe true
            link.progress.value.error.shouldBeInstanceOf<TlogTruncated>()
        }
    }

    "opened paused, a replay delivers nothing until play, then paces the log from that moment; closed while paused, it returns" {
        val records = twoCopters().take(20)
        val file = tempfile(suffix = ".tlog").writeTlog(records)
        runTest {
            val link = TlogReplayLink.open(file.toPath(), speed = 2.0, timebase = virtualTimebase(), paused = true)
            val delivered = mutableListOf<Long>()
            val receiving = backgroundScope.launch { link.receive { _, _ -> delivered += testScheduler.currentTime } }
            testScheduler.advanceTimeBy(10_000)
            testScheduler.runCurrent()
            delivered shouldBe emptyList()
            link.play()
            receiving.join()
            delivered.size shouldBe 20
            delivered.first() shouldBe 10_000L
            // The 20th record is 1.500002 s of log after the first: 0.75 s at 2x, counted from play
            // (the scheduler's delays round up to whole milliseconds).
            delivered.last() shouldBeInRange 10_750L..10_751L
            val idle = TlogReplayLink.open(file.toPath(), timebase = virtualTimebase(), paused = true)
            val waiting = backgroundScope.launch { idle.receive { _, _ -> throw AssertionError("a closed replay delivered a frame") } }
            testScheduler.runCurrent()
            idle.close()
            waiting.join()
            idle.progress.value.records shouldBe 0L
        }
    }

    "closed before it plays, a replay delivers nothing; what is sent to it goes nowhere; the speed is checked" {
        val file = tempfile(suffix = ".tlog").writeTlog(twoCopters())
        runTest {
            val link = TlogReplayLink.open(file.toPath(), timebase = virtualTimebase())
            link.peers shouldBe emptyList()
            link.send(copterHeartbeat(9, 0), TlogReplayLink.RECORDING)
            link.sendNow(copterHeartbeat(9, 0), TlogReplayLink.RECORDING)
            link.close()
            var count = 0
            link.receive { _, _ -> count++ }
            count shouldBe 0
            link.progress.value.finished shouldBe false
        }
        for (speed in listOf(0.0, -1.0, Double.NaN, Double.NEGATIVE_INFINITY)) {
            shouldThrow<IllegalArgumentException> { TlogReplayLink.open(file.toPath(), speed) }.message shouldBe "speed must be a number > 0, was $speed"
        }
        shouldThrow<TlogException> { TlogReplayLink.open(File(file.parentFile, "missing.tlog").toPath()) }
    }
})
