package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.double
import com.github.ajalt.clikt.parameters.types.long
import com.github.ajalt.clikt.parameters.types.path
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.runBlocking
import pod.cli.json.Event
import pod.cli.json.EventJson
import pod.cli.json.toEvent
import pod.launch.Interrupted
import pod.launch.Interruption
import pod.launch.SurveyPicture
import pod.launch.simulate
import pod.launch.surveySvg
import pod.samples.iSeed
import pod.samples.iSeedObjects
import pod.samples.iSeedWorld
import pod.sim.SimFlavor
import kotlin.io.path.Path
import kotlin.io.path.writeText

/**
 * `pod survey`: the I-Seed scenario ([iSeed]) on a simulated drone over a seeded field (objects,
 * a hill, a rangefinder): the operator's app states as they change, a summary of both passes, and
 * an SVG map of the polygon, the forward path, the detections and the backward path.
 */
internal class SurveyCommand(private val out: Output) : CliktCommand(name = "survey") {
    private val timeScale by option("--time-scale", help = "how much faster than real time the drone lives").double().restrictTo(1.0..200.0).default(40.0)
    private val seed by option("--seed", help = "where the simulated objects lie").long().default(7)
    private val map by option("--map", help = "where to write the SVG map").path().default(Path("pod-survey-map.svg"))
    private val json by option("--json", help = "JSON lines instead of text").flag()

    override fun help(context: Context): String =
        "The I-Seed survey workflow on a simulated drone: an operator's app builds a path over a field, starts, pauses and resumes it; the drone photographs every waypoint, revisits those whose photo detected objects to measure their range, and lands at home."

    override fun run() = runBlocking {
        LocalFiles.checkWritable(map.toString())
        var done: Event.SurveyDone? = null
        try {
            val (outcome, record) = simulate(
                flavors = listOf(SimFlavor.ARDUCOPTER),
                timeScale = timeScale,
                onLine = { if (!json) out.line(it) },
                onEvent = { if (json) it.toEvent()?.let { e -> out.line(EventJson.encode(e)) } },
                configure = iSeedWorld(seed),
            ) { Interruption.cancellable { iSeed() } }
            val run = outcome.run
            val picture = SurveyPicture(
                polygon = outcome.field,
                plan = outcome.plan,
                forwardFlagged = run.flagged,
                backwardOrder = run.backward.map { it.first },
                vehicleName = outcome.vehicle.name,
                objects = iSeedObjects(outcome.home, seed).map { it.location },
                track = record.tracks[outcome.vehicle.id]?.second.orEmpty(),
                vehicleId = outcome.vehicle.id,
            )
            map.writeText(surveySvg(picture, "I-Seed survey on ${outcome.vehicle.name}"))
            done = Event.SurveyDone(
                ok = true, error = null,
                photos = run.forward.size,
                detections = run.forward.sumOf { it.result?.value?.size ?: 0 },
                flagged = run.flagged,
                backward = run.backward.map { (index, r) -> Event.Measured(index, r.result?.meters) },
                map = map.toString(),
            )
        } catch (e: Interrupted) {
            out.line(if (json) EventJson.encode(Event.Interrupted(e.signal, map = null)) else "interrupted by ${e.signal}: survey stopped")
            throw CliktError("pod: stopped by ${e.signal}", statusCode = Interruption.EXIT_CODE)
        } catch (e: CliktError) {
            throw e
        } catch (e: Exception) {
            done = Event.SurveyDone(false, e.message ?: e::class.simpleName, null, null, null, null, map.toString())
        }
        val end = done!!
        if (json) {
            out.line(EventJson.encode(end))
        } else if (end.ok) {
            out.line("forward: ${end.photos} photos, ${end.detections} detections, ${end.flagged!!.size} waypoints flagged")
            end.backward!!.forEach { out.line("backward: waypoint ${it.waypoint} range ${it.rangeM?.let { r -> "%.1f m".format(r) } ?: "not measured"}") }
            out.line("survey done; map: $map")
        } else {
            out.line("survey failed: ${end.error}")
        }
        if (!end.ok) throw CliktError("survey failed: ${end.error}", statusCode = 1)
    }
}
