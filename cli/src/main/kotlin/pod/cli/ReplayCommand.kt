package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.options.validate
import com.github.ajalt.clikt.parameters.types.path
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import kotlinx.coroutines.yield
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.launch.Interrupted
import pod.launch.Interruption
import pod.launch.map.FlightMap
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.tlog.TlogCorrupt
import pod.mavlink.tlog.TlogException
import pod.mavlink.tlog.TlogReader
import pod.mavlink.tlog.TlogReplayLink
import pod.mavlink.tlog.TrackRecorder
import java.nio.file.Path
import kotlin.time.Duration.Companion.seconds
import kotlin.time.DurationUnit

/**
 * `pod replay FILE.tlog`: plays a recorded flight to a ground station as if it were live, showing
 * what `pod watch` would have shown (the fleet table, or `--json` lines), `--speed` times faster,
 * and drawing the tracks it saw with `--map`.
 */
internal class ReplayCommand(private val out: Output) : CliktCommand(name = "replay") {
    private val file by argument("FILE", help = "the tlog to play (Pod's, MAVProxy's or pymavlink's)")
    private val speed by option("--speed", help = "how many times faster than recorded to play it, or max: as fast as it can")
        .convert { if (it == "max") Double.POSITIVE_INFINITY else it.toDoubleOrNull() ?: fail("must be a number > 0 or max, was $it") }
        .default(1.0).validate { require(it > 0.0) { "must be a number > 0 or max, was $it" } }
    private val json by option("--json", help = "one JSON object per event or update, per line").flag()
    private val map by option("--map", help = "where to write the tracks the replay showed: .svg, .geojson or .kml").path()
    private val lostAfter by option("--lost-after", help = "log time of silence after which a vehicle is marked lost ($DURATION_FORMAT)")
        .convert { it.toDurationOrNull() ?: fail(NOT_A_DURATION.format(it)) }.default(3.seconds)

    override fun help(context: Context): String = "Play a recorded tlog to a ground station as if live."

    override fun run() = runBlocking {
        // The map is written at the end: a path that cannot take it fails now, not after the replay.
        map?.let { LocalFiles.checkMapOutput(it.toString()) }
        val path = checkedTlog()
        val link = try {
            TlogReplayLink.open(path, speed, paused = true)
        } catch (e: TlogException) {
            badInput(e.message!!)
        }
        // A log cannot answer: the station asks it for nothing. The station lives in log time
        // (TlogReplayLink.logTimebase): it reads the log's clock and its timers, the silence check
        // among them, fire as the log passes their time, so a vehicle is lost after --lost-after of
        // log whatever the speed, and a process that falls behind only plays late.
        val config = GroundStationConfig(
            lostAfter = lostAfter, streamRates = emptyMap(), requestHome = false, requestPayloads = false,
            timebase = link.logTimebase,
        )
        val gcs = GroundStation.open(link, this, config)
        val tracks = TrackRecorder()
        val recording = gcs.record(tracks)
        val view = LiveView(out, json)
        if (json) out.line(EventJson.encode(Event.Replaying(file, speed.takeIf { it.isFinite() }))) else view.note("replaying $file " + if (speed.isFinite()) "at ${speed}x" else "as fast as it can")
        try {
            val playing: suspend () -> Unit = {
                coroutineScope {
                    val subscribed = CompletableDeferred<Unit>()
                    val shown = launch { view.show(gcs, subscribed) }
                    // Played only now that the tracks are recorded and the fleet's events watched: at a
                    // high speed the whole log can play before a view launched beside it subscribes, and
                    // a vehicle lost and regained in that time would show only as regained.
                    subscribed.await()
                    link.play()
                    link.progress.first { it.finished }
                    // At --speed max the log can be played before this coroutine or the view's ever ran
                    // (first returns at once): every fleet event was emitted before the log finished, so
                    // the view's resumption is queued ahead of ours on this event loop; yielding lets it
                    // print them before it is cancelled.
                    yield()
                    shown.cancel()
                }
            }
            // With a map to write, Ctrl-C ends the replay and the map still shows what was played.
            if (map == null) playing() else Interruption.cancellable("writing the map") { playing() }
            view.finish(gcs)
        } catch (e: Interrupted) {
            view.stop()
            writeMap(tracks)
            throw CliktError("pod: stopped by ${e.signal}; ${link.progress.value.records} records played${map?.let { "; map so far: $it" } ?: ""}", statusCode = Interruption.EXIT_CODE)
        } finally {
            recording.stop()
            withContext(NonCancellable) { gcs.closeAndAwait() }
        }
        writeMap(tracks)
        val done = link.progress.value
        val logSeconds = done.logTime.toDouble(DurationUnit.SECONDS)
        if (json) {
            out.line(EventJson.encode(Event.ReplayDone(done.records, logSeconds, done.error?.message, map?.toString())))
        } else {
            done.error?.let { out.line("warning: $file: ${it.message}; played the ${done.records} records before it") }
            out.line("replayed ${done.records} records, %.1f s of log, from $file".format(java.util.Locale.ROOT, logSeconds) + (map?.let { "; map: $it" } ?: ""))
        }
        // A record cut short ends most logs whose recorder was killed: what came before is whole.
        // Bytes that are not a frame part way through are damage: the rest of the log is lost.
        if (done.error is TlogCorrupt) throw CliktError("error: $file is corrupt: ${done.error!!.message}", statusCode = Exit.FAILED)
    }

    /** The tlog to play: an existing file that starts with one whole record. */
    private fun checkedTlog(): Path {
        val path = LocalFiles.tlogPath(file)
        try {
            TlogReader.open(path).use { it.next() } ?: badInput("$file is empty: no tlog record to play")
        } catch (e: TlogException) {
            // Not one whole record: not a tlog at all, rather than one cut short.
            badInput("$file is not a tlog: ${e.message}")
        }
        return path
    }

    private fun writeMap(tracks: TrackRecorder) {
        val target = map ?: return
        val drawn = FlightMap("replay of ${Path.of(file).fileName}")
        tracks.tracks().forEach(drawn::track)
        LocalFiles.writeMap(drawn, target.toString())
    }
}
