package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.double
import com.github.ajalt.clikt.parameters.types.long
import com.github.ajalt.clikt.parameters.types.path
import com.github.ajalt.clikt.parameters.types.restrictTo
import kotlinx.coroutines.runBlocking
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

    override fun help(context: Context): String =
        "The I-Seed survey workflow on a simulated drone: an operator's app builds a path over a field, starts, pauses and resumes it; the drone photographs every waypoint, revisits those whose photo detected objects to measure their range, and lands at home."

    override fun run() = runBlocking {
        LocalFiles.checkWritable(map.toString())
        try {
            val (outcome, record) = simulate(
                flavors = listOf(SimFlavor.ARDUCOPTER),
                timeScale = timeScale,
                onLine = { out.line(it) },
                configure = iSeedWorld(seed),
            ) { Interruption.cancellable { iSeed() } }
            val run = outcome.run
            val detections = run.forward.sumOf { it.result?.value?.size ?: 0 }
            out.line("forward: ${run.forward.size} photos, $detections detections, ${run.flagged.size} waypoints flagged")
            run.backward.forEach { (index, r) -> out.line("backward: waypoint $index range ${r.result ?: "not measured"}") }
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
            out.line("survey done; map: $map")
        } catch (e: Interrupted) {
            throw CliktError("pod: stopped by ${e.signal}", statusCode = Interruption.EXIT_CODE)
        } catch (e: CliktError) {
            throw e
        } catch (e: Exception) {
            throw CliktError("survey failed: ${e.message}", statusCode = 1)
        }
    }
}
