package pod.mavlink.tlog

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.engine.spec.tempfile
import io.kotest.matchers.longs.shouldBeInRange
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import pod.core.vehicle.ConnectionState
import pod.mavlink.FleetEvent
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.copterHeartbeat
import pod.mavlink.virtualTimebase
import kotlin.time.Duration.Companion.seconds

private const val T0 = 1_700_000_000_000_000L

/**
 * An hour of two copters' heartbeats at 1 Hz. Vehicle 1 skips two and sends one half-way instead
 * (2.5 s of silence at 999 s, under the 3 s limit); vehicle 2 says nothing from 1800 s to 1860 s.
 */
private fun hourWithGaps(): List<TlogRecord> = buildList {
    for (second in 0 until 3600) {
        val t = T0 + second * 1_000_000L
        if (second == 1001) add(TlogRecord(t + 500_000, copterHeartbeat(1, second)))
        if (second != 1000 && second != 1001) add(TlogRecord(t, copterHeartbeat(1, second)))
        if (second !in 1800 until 1860) add(TlogRecord(t + 10, copterHeartbeat(2, second)))
    }
}

class LogTimeReplayTest : StringSpec({

    "on the log's timebase a station counts silence in log time at any speed: no heartbeat gap under lostAfter is a loss, one over it is, at its log time" {
        val records = hourWithGaps()
        val file = tempfile(suffix = ".tlog")
        TlogWriter.create(file.toPath()).use { w -> records.forEach { w.write(it.timestampMicros, it.frame) } }
        for (speed in listOf(5_000.0, Double.POSITIVE_INFINITY)) {
            runTest {
                val link = TlogReplayLink.open(file.toPath(), speed, timebase = virtualTimebase(), paused = true)
                val gcs = GroundStation.open(
                    link, backgroundScope,
                    GroundStationConfig(lostAfter = 3.seconds, streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = link.logTimebase),
                )
                val events = mutableListOf<FleetEvent>()
                backgroundScope.launch { gcs.events.toList(events) }
                testScheduler.runCurrent() // the station's loops and the collector are in place
                link.play()
                link.progress.first { it.finished }
                testScheduler.runCurrent()
                withClue("speed $speed: ${events.map { "${it::class.simpleName} ${it.vehicle.systemId}" }}") {
                    link.progress.value.records shouldBe records.size.toLong()
                    events.filterIsInstance<FleetEvent.Lost>().map { it.vehicle.systemId } shouldBe listOf(2)
                    // Last heard at 1799 s; the check runs every 250 ms of log: lost at 1802.25 s.
                    events.filterIsInstance<FleetEvent.Lost>().single().silence.inWholeMilliseconds shouldBeInRange 3_001L..3_250L
                    events.filterIsInstance<FleetEvent.Regained>().map { it.vehicle.systemId } shouldBe listOf(2)
                    gcs.vehicles.value.values.map { it.connection.value }.toSet() shouldBe setOf(ConnectionState.CONNECTED)
                    // Paced, the hour (its last record at 3599 s) takes 720 ms of the pacing clock at 5000x; unpaced, none.
                    testScheduler.currentTime shouldBeInRange if (speed.isFinite()) 719L..721L else 0L..0L
                }
                gcs.close()
            }
        }
    }
})
