package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.double
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.path
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.cli.json.toEvent
import pod.cli.gcs.GcsRequestException
import pod.cli.gcs.GcsWatcher
import pod.cli.gcs.HttpAddress
import pod.cli.gcs.gcsOption
import pod.cli.json.GcsServing
import pod.launch.FleetWatcher
import pod.launch.Interruption
import pod.mavlink.GroundStation
import pod.launch.Interrupted
import pod.dsl.action
import pod.dsl.and
import pod.samples.listing4
import pod.samples.queueTour
import pod.launch.simulate
import pod.sim.SimFlavor
import kotlin.io.path.Path
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/**
 * `pod demo`: the Dolphin report's Listing 4 on simulated drones at an accelerated time scale —
 * two vehicles kept on survey, each replaced by a charged one when its battery runs low — and,
 * beside it on one more drone, a mission queue fed while it flies ([queueTour]), printing
 * every task and vehicle event as it happens under a live fleet table, then an SVG map of the
 * planned missions and the flown tracks.
 */
internal class DemoCommand(private val out: Output) : CliktCommand(name = "demo") {
    private val count by option("--vehicles", help = "how many simulated drones").int().restrictTo(3..20).default(5)
    private val timeScale by option("--time-scale", help = "how much faster than real time the vehicles live").double().restrictTo(1.0..200.0).default(40.0)
    private val length by option("--for", help = "how long the fleet keeps two drones on survey, in vehicle time (e.g. 30m; $DURATION_FORMAT)")
        .convert { text -> text.toDurationOrNull() ?: fail(NOT_A_DURATION.format(text)) }
        .default(30.minutes)
    private val map by option("--map", help = "where to write the map of missions and tracks: .svg, .geojson or .kml").path().default(Path("pod-demo-map.svg"))
    private val json by option("--json", help = "JSON lines instead of text").flag()
    private val gcs by gcsOption()

    override fun help(context: Context): String =
        "Dolphin's Listing 4 on simulated drones (two kept on survey, each replaced by a charged one when its battery runs low), and a mission queue fed while one more flies it."

    override fun run() = runBlocking {
        // The map is written at the end: a path that cannot take it fails now, not after the flight.
        LocalFiles.checkMapOutput(map.toString())
        val view = LiveView(out, json, period = if (json) 20.seconds else 5.seconds)
        var failed: Throwable? = null
        var page: FleetWatcher.Watch? = null
        try {
            simulate(
                flavors = List(count) { SimFlavor.ARDUCOPTER },
                timeScale = timeScale,
                onLine = { if (!json) view.note(it) },
                onEvent = { page?.event(it); if (json) it.toEvent()?.let { e -> out.line(EventJson.encode(e)) } },
                map = map,
            ) { sim ->
                val shown = launch { view.show(sim.station) }
                view.note("$count simulated drones at ${timeScale}x; keeping 2 on survey for $length of vehicle time, and one flying a mission queue")
                try {
                    page = gcs?.let { at -> servePage(at, sim.station, view) }
                    Interruption.cancellable { execute(action("queue tour") { queueTour() } and action("listing 4") { listing4(duration = length) }) }
                } finally {
                    shown.cancel()
                    page?.close()
                    view.finish(sim.station)
                }
            }
        } catch (e: CliktError) {
            throw e
        } catch (e: Interrupted) {
            // The drones live in this process and stop with it; the cancelled program made them safe first.
            out.line(if (json) EventJson.encode(Event.Interrupted(e.signal, map = map.toString())) else "interrupted by ${e.signal}: demo stopped; map so far: $map")
            throw CliktError("pod: stopped by ${e.signal}", statusCode = Interruption.EXIT_CODE)
        } catch (e: Exception) {
            failed = e
        }
        if (json) out.line(EventJson.encode(Event.DemoDone(ok = failed == null, error = failed?.let { it.message ?: it::class.simpleName }, map = map.toString())))
        else out.line(if (failed == null) "demo done; map of missions and tracks: $map" else "demo failed: ${failed.message}; map so far: $map")
        if (failed != null) throw CliktError("demo failed: ${failed.message}", statusCode = 1)
    }

    // `--gcs`: the demo's fleet on the ground station's page too, its program's events in the page's log.
    private suspend fun servePage(at: HttpAddress, station: GroundStation, view: LiveView): FleetWatcher.Watch = try {
        GcsWatcher(at) { server ->
            if (json) out.line(EventJson.encode(GcsServing(server.url))) else view.note("ground station: open ${server.url}")
        }.watch(station, timeScale, "pod demo: $count simulated copters")
    } catch (e: GcsRequestException) {
        badInput(e.message!!)
    }
}
