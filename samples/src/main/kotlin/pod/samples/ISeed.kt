package pod.samples

import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.distinctUntilChangedBy
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.transformWhile
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import pod.core.engine.Program
import pod.core.platform.PlatformVehicle
import pod.core.survey.CameraTrigger
import pod.core.survey.PolygonSurvey
import pod.core.survey.SurveyPlan
import pod.core.survey.SurveySpacing
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import pod.core.workflow.ControlCommand
import pod.core.workflow.ControlPhase
import pod.core.workflow.MissionControl
import pod.core.workflow.SurveyRun
import pod.dsl.action
import pod.dsl.and
import pod.dsl.idle
import pod.dsl.pick
import pod.dsl.survey.flag
import pod.dsl.survey.on
import pod.dsl.survey.pass
import pod.dsl.survey.surveyService
import pod.sim.SimDetections
import pod.sim.SimVehicleConfig
import pod.sim.world.Hill
import pod.sim.world.Rangefinder
import pod.sim.world.SimObject
import pod.sim.world.Terrain
import kotlin.time.Duration.Companion.seconds

/** What the I-Seed scenario flew: the field, the path the operator built, and what each pass recorded. */
public class ISeedOutcome(
    /** The drone that flew it. */
    public val vehicle: PlatformVehicle,
    /** Its home. */
    public val home: Location,
    /** The operator's polygon. */
    public val field: List<Location>,
    /** The path built from it. */
    public val plan: SurveyPlan,
    /** Each photo's detected object ids (forward), each flagged waypoint's range (backward). */
    public val run: SurveyRun<List<Int>, Distance>,
    /** The phases the operator's app showed, in order. */
    public val phases: List<ControlPhase>,
)

/** The I-Seed field: an L-shaped (concave) polygon north-east of [home]. */
public fun iSeedField(home: Location): List<Location> =
    listOf(30 to 30, 30 to 190, 110 to 190, 110 to 110, 170 to 110, 170 to 30).map { (n, e) -> home.offset(n.m, e.m) }

/**
 * The simulated world of the I-Seed scenario for seed [seed]: objects scattered over the field, a
 * hill under it, and a downward rangefinder on every drone (pass it to `simulate(configure = …)`).
 */
public fun iSeedWorld(seed: Long): (SimVehicleConfig) -> SimVehicleConfig = { config ->
    val home = config.home
    config.copy(
        objects = iSeedObjects(home, seed),
        terrain = Terrain(origin = home, hills = listOf(Hill(north = 110.m, east = 120.m, height = 10.m, radius = 45.m))),
        rangefinder = Rangefinder(),
    )
}

/** The objects lying around the I-Seed field of [home] for seed [seed]. */
public fun iSeedObjects(home: Location, seed: Long): List<SimObject> =
    SimObject.scatter(seed = seed, count = 8, center = home.offset(100.m, 100.m), radius = 70.m)

/**
 * The I-Seed onboard service rebuilt on Pod: an operator's app ([MissionControl]) and a drone
 * serving it ([surveyService]). The app waits for the drone to be ready, builds a path over the
 * field (a photo at every waypoint), starts it, pauses it for 20 s in the forward pass and resumes;
 * the drone photographs every waypoint and flags the ones whose photo detected objects (the
 * simulator says what each photo saw), revisits only those on the backward pass and measures the
 * range there, keeping 30 m above the ground over the hill, then lands at home.
 */
public suspend fun Program.iSeed(): ISeedOutcome {
    val v = pick { count(1) }[0]
    val home = homeOf(v)
    val field = iSeedField(home)
    val control = MissionControl<SurveyPlan>()
    val survey = surveyService(
        control,
        forward = {
            val seen = SimDetections.parse(takePhoto().fileUrl)?.ids.orEmpty()
            if (seen.isEmpty()) pass(seen) else flag(seen)
        },
        backward = { measureRange() },
    ) { correctAltitude(target = 30.m, minimum = 10.m, maximum = 80.m) }
    // What the app shows, as it shows it; the app acts on what it has shown.
    val shown = MutableStateFlow(listOf<ControlPhase>())
    val app = action("operator's app") {
        coroutineScope {
            val showing = launch(start = CoroutineStart.UNDISPATCHED) {
                control.state
                    .distinctUntilChangedBy { it.phase }
                    .transformWhile { emit(it); it.phase != ControlPhase.Finished && it.phase !is ControlPhase.Aborted }
                    .collect { s ->
                        shown.update { it + s.phase }
                        message("app: ${describe(s.phase)} (event ${s.eventId})")
                    }
            }
            shown.first { ControlPhase.Ready in it }
            val plan = PolygonSurvey.plan(field, 30.m, SurveySpacing.Direct(40.m), start = home, trigger = CameraTrigger.PER_WAYPOINT)
            control.command(ControlCommand.Build(control.nextEventId(), plan))
            control.command(ControlCommand.Start(control.nextEventId()))
            control.state.first { ((it.phase as? ControlPhase.Executing)?.waypoint ?: 0) >= 4 }
            control.command(ControlCommand.Pause(control.nextEventId()))
            execute(idle(20.seconds))
            control.command(ControlCommand.Resume(control.nextEventId()))
            showing.join()
        }
    }
    execute((survey on v) and app)
    release(v)
    return ISeedOutcome(v, home, field, survey.plan.value!!, survey.result.value!!, shown.value)
}

private fun describe(phase: ControlPhase): String = when (phase) {
    ControlPhase.Waiting -> "waiting for the drone"
    ControlPhase.Ready -> "drone ready"
    ControlPhase.PathBuilt -> "path built"
    is ControlPhase.Executing -> "executing the ${phase.pass.name.lowercase()} pass" + (phase.waypoint?.let { ", waypoint $it" } ?: "")
    is ControlPhase.Paused -> "paused in the ${phase.pass.name.lowercase()} pass" + (phase.waypoint?.let { " at waypoint $it" } ?: "")
    ControlPhase.Finished -> "finished: landed at home"
    is ControlPhase.Aborted -> "aborted: ${phase.reason}"
}
