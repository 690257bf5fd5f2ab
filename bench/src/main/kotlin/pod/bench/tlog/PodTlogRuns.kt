package pod.bench.tlog

import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.vehicle.ConnectionState
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.tlog.LoggedFlight
import pod.mavlink.tlog.TlogReader
import pod.mavlink.tlog.TlogReplayLink
import pod.mavlink.tlog.TlogTracks
import pod.mavlink.tlog.TrackRecorder
import java.lang.management.ManagementFactory
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * One timed pass over the log: wall and process CPU time, records seen, and what it found wrong
 * ([problems]: the pass read something else than the log holds) or worth telling ([notes]).
 */
data class Pass(
    val wallSeconds: Double,
    val cpuSeconds: Double?,
    val records: Long,
    val problems: List<String> = emptyList(),
    val notes: List<String> = emptyList(),
)

/** Pod's passes over a tlog: reading its tracks, reading bare records, replaying it to a station. */
object PodTlogRuns {
    private val os = ManagementFactory.getOperatingSystemMXBean() as? com.sun.management.OperatingSystemMXBean

    /** CPU time of this whole JVM (every thread: the work, JIT, GC), or null where the JDK does not say. */
    private fun processCpuSeconds(): Double? = os?.processCpuTime?.takeIf { it >= 0 }?.let { it / 1e9 }

    private class Outcome(val records: Long, val problems: List<String>)

    /** Times [block] after a GC, so that one pass's garbage is not collected on the next one's clock. */
    private inline fun timed(block: () -> Outcome): Pass {
        System.gc()
        val cpu0 = processCpuSeconds()
        val t0 = System.nanoTime()
        val outcome = block()
        val wall = (System.nanoTime() - t0) / 1e9
        val cpu = processCpuSeconds()?.let { end -> cpu0?.let { end - it } }
        return Pass(wall, cpu, outcome.records, outcome.problems)
    }

    /** [TlogTracks.read] with a step of 0 m, so every position is a point and the counts can be checked. */
    fun readTracks(path: Path, expected: LogContents): Pass = timed {
        val flight = TlogTracks.read(path, stepMetres = 0.0)
        Outcome(flight.records, checkRead(flight, expected))
    }

    /** [TlogReader.next] to the end: framing and checksum only, nothing decoded — the floor under [readTracks]. */
    fun readRecords(path: Path, expected: LogContents): Pass = timed {
        var records = 0L
        var bytes = 0L
        TlogReader.open(path).use { reader ->
            while (true) {
                val record = reader.next() ?: break
                records++
                bytes += 8 + record.frame.size
            }
        }
        val problems = buildList {
            if (records != expected.records) add("read $records records, the log has ${expected.records}")
            if (bytes != expected.bytes) add("read $bytes bytes, the log has ${expected.bytes}")
        }
        Outcome(records, problems)
    }

    /**
     * The log played through a [TlogReplayLink] at [speed] to a [GroundStation], wired as `pod replay`
     * wires it (opened paused, its station configuration, a [TrackRecorder] tap when [withTracks],
     * played once the tap is in place, waiting on the link's progress), from opening the station to
     * the replay's end. Checked: every record played, each vehicle's last position on the station
     * equal to its last GLOBAL_POSITION_INT in the log, and the recorder's track holding every one.
     */
    suspend fun replay(path: Path, speed: Double, withTracks: Boolean, expected: LogContents, limit: Duration): Pass = coroutineScope {
        System.gc()
        val link = TlogReplayLink.open(path, speed, paused = true)
        // As `pod replay` (issue 30): the station in log time, lost after 3 s of log silence.
        val config = GroundStationConfig(
            lostAfter = 3.seconds, streamRates = emptyMap(), requestHome = false, requestPayloads = false, timebase = link.logTimebase,
        )
        val cpu0 = processCpuSeconds()
        val t0 = System.nanoTime()
        val station = GroundStation.open(link, this, config)
        val tracks = if (withTracks) TrackRecorder(stepMetres = 0.0) else null
        val recording = tracks?.let { station.record(it) }
        link.play()
        try {
            val done = withTimeoutOrNull(limit) { link.progress.first { it.finished } }
            val wall = (System.nanoTime() - t0) / 1e9
            val cpu = processCpuSeconds()?.let { end -> cpu0?.let { end - it } }
            val progress = link.progress.value
            val problems = mutableListOf<String>()
            val notes = mutableListOf<String>()
            if (done == null) problems += "replay not finished within $limit (${progress.records} records played)"
            if (progress.error != null) problems += "replay ended early: ${progress.error!!.message}"
            if (progress.records != expected.records) problems += "played ${progress.records} records, the log has ${expected.records}"
            val vehicles = station.vehicles.value
            if (vehicles.keys != expected.last.keys) problems += "station shows vehicles ${vehicles.keys}, the log has ${expected.last.keys}"
            for ((id, last) in expected.last) {
                val shown = vehicles[id]?.telemetry?.position?.value?.location
                if (shown != last.location()) problems += "vehicle $id: station shows $shown, its last GLOBAL_POSITION_INT is ${last.location()}"
            }
            // The log has no gap: in log time nobody is lost, at any speed.
            val lost = vehicles.values.count { it.connection.value == ConnectionState.LOST }
            if (lost > 0) problems += "$lost vehicles marked lost at the end"
            tracks?.tracks()?.let { recorded ->
                for ((id, count) in expected.positions) {
                    val points = recorded.firstOrNull { it.systemId == id }?.points?.size ?: 0
                    // Before the replay could open paused, the first frames went by before the tap was in.
                    if (points != count) problems += "TrackRecorder: vehicle $id has $points of its $count positions"
                }
            }
            Pass(wall, cpu, progress.records, problems, notes)
        } finally {
            recording?.stop()
            station.closeAndAwait()
        }
    }

    /** What a reader of the log must have found: every record, every position, each vehicle's last one. */
    private fun checkRead(flight: LoggedFlight, expected: LogContents): List<String> = buildList {
        flight.error?.let { add("read stopped early: ${it.message}") }
        if (flight.records != expected.records) add("read ${flight.records} records, the log has ${expected.records}")
        val ids = flight.tracks.map { it.systemId }.toSet()
        if (ids != expected.positions.keys) add("tracks of vehicles $ids, the log has ${expected.positions.keys}")
        for (track in flight.tracks) {
            val count = expected.positions[track.systemId] ?: continue
            if (track.points.size != count) add("vehicle ${track.systemId}: ${track.points.size} positions, the log has $count")
            val last = expected.last.getValue(track.systemId).location()
            if (track.points.lastOrNull() != last) add("vehicle ${track.systemId}: track ends at ${track.points.lastOrNull()}, the log at $last")
        }
    }
}
