package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.path
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.mavlink.GroundStation
import pod.launch.Interrupted
import pod.launch.Interruption
import pod.mavlink.GroundStationConfig
import pod.mavlink.tlog.TlogException
import pod.mavlink.tlog.TlogWriter
import kotlin.time.Duration.Companion.seconds

/** `pod watch`: shows every vehicle on a link, Pod's or not, live. */
internal class WatchCommand(private val out: Output) : CliktCommand(name = "watch") {
    private val connect by option("--connect", help = "link to listen on or connect to (udpin:, udpout:, tcp:, serial:///dev/ttyUSB0:57600)")
        .default("udpin:0.0.0.0:14550")
    private val json by option("--json", help = "one JSON object per event or update, per line").flag()
    private val duration by option("--duration", help = "stop after this long ($DURATION_FORMAT); default: until interrupted")
        .convert { it.toDurationOrNull() ?: fail(NOT_A_DURATION.format(it)) }
    private val lostAfter by option("--lost-after", help = "silence after which a vehicle is marked lost ($DURATION_FORMAT)")
        .convert { it.toDurationOrNull() ?: fail(NOT_A_DURATION.format(it)) }.default(3.seconds)
    private val keyFile by keyFileOption()
    private val record by option("--record", help = "write every frame sent and received to this tlog (MAVProxy's and pymavlink's format)")
        .path()

    override fun help(context: Context): String = "Show the vehicles on a MAVLink link, live."

    override fun run() = runBlocking {
        val gcs = reportingLinkErrors {
            GroundStation.open(connect, this, signedConfig(signingKey(keyFile), GroundStationConfig(lostAfter = lostAfter), WATCH_LINK_ID))
        }
        // Opened after the link, so a bad address leaves no empty file behind.
        val writer = record?.let { path ->
            try {
                TlogWriter.create(path)
            } catch (e: TlogException) {
                gcs.closeAndAwait()
                badInput(e.message!!)
            }
        }
        val recording = writer?.let { gcs.record(it) }
        val view = LiveView(out, json)
        if (json) {
            out.line(EventJson.encode(Event.Listening(gcs.link.address.toString(), gcs.link.localPort)))
        } else {
            view.note("listening on ${gcs.link.address} (local port ${gcs.link.localPort})")
        }
        try {
            val limit = duration
            // While recording, Ctrl-C cancels the watch instead of ending the process at once, so
            // the tlog is flushed and closed below: it ends after a whole record.
            val watching: suspend () -> Unit = { if (limit == null) view.show(gcs) else withTimeoutOrNull(limit) { view.show(gcs) } }
            if (writer == null) watching() else Interruption.cancellable("closing the tlog") { watching() }
            view.finish(gcs)
        } catch (e: Interrupted) {
            throw CliktError("pod: stopped by ${e.signal}; ${writer?.records} frames recorded to $record", statusCode = Interruption.EXIT_CODE)
        } finally {
            recording?.stop()
            // The next command may bind the same udpin port at once: release it before returning.
            withContext(NonCancellable) { gcs.closeAndAwait() }
            writer?.close()
        }
        gcs.linkError.value?.let { reportingLinkErrors { throw it } }
        Unit
    }
}
