package pod.mavlink.workflow

import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import pod.core.units.Distance
import pod.core.workflow.ControlReport
import pod.core.workflow.SurveyAborted
import pod.core.workflow.SurveyJob
import pod.mavlink.MavlinkVehicle
import pod.mavlink.queue.QueueFlightConfig

/**
 * Flies the engine's survey [job] on [vehicle] (`Platform.flySurvey`): at once over its area, or
 * serving its mission control for one flight. Fills the job's plan and result; an operator's abort
 * or a failure reported by the flight ends it with [SurveyAborted].
 */
internal suspend fun <F, B> flySurveyJob(vehicle: MavlinkVehicle, job: SurveyJob<F, B>, timeScale: Double, config: QueueFlightConfig) {
    val s = job.settings
    val workflow = SurveyWorkflow(vehicle, config, timeScale, s.actionTimeout, s.onFailure, s.homeTimeout, s.altitudeCorrection)
    val control = job.control
    if (control == null) {
        val area = job.area!!
        takeOffIfOnGround(vehicle, area.height)
        val plan = area.plan(vehicle.telemetry.position.value?.location)
        job.planned(plan)
        job.finished(workflow.run(plan, { job.forward(it) }, { job.backward(it) }))
        return
    }
    // The program owns the vehicle: flown up before this task, it is ready for the operator's path.
    val operation = SurveyOperation(vehicle, control, workflow, { job.forward(it) }, { job.backward(it) }, readyInTheAir = true)
    coroutineScope {
        val planning = launch { control.intent.collect { it.state.plan?.let(job::planned) } }
        operation.serve(flights = 1)
        planning.cancel()
    }
    operation.runs.value.lastOrNull()?.let(job::finished)
    (operation.latest.value as? ControlReport.Stopped)?.let { throw SurveyAborted(it.reason) }
}

/** Arms and takes off to [height] above home when [vehicle] is on the ground; nothing when it flies ([pod.mavlink.action.VehicleActions.getAirborne]). */
internal suspend fun takeOffIfOnGround(vehicle: MavlinkVehicle, height: Distance) {
    vehicle.action.getAirborne(height)
}
