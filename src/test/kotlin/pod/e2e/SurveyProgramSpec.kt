package pod.e2e

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.collections.shouldNotBeEmpty
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.shouldBe
import pod.core.engine.EngineEvent
import pod.core.survey.SurveySpacing
import pod.core.units.m
import pod.core.vehicle.LandedState
import pod.core.workflow.ControlPhase
import pod.core.workflow.Pass
import pod.core.workflow.SurveyNeedsOneVehicle
import pod.core.workflow.SurveyAborted
import pod.core.workflow.ControlCommand
import pod.core.workflow.MissionControl
import pod.core.survey.SurveyPlan
import pod.core.survey.PolygonSurvey
import pod.core.survey.CameraTrigger
import pod.dsl.action
import pod.dsl.and
import pod.dsl.survey.surveyService
import io.kotest.matchers.types.shouldBeInstanceOf
import kotlinx.coroutines.flow.first
import pod.dsl.mission
import pod.dsl.on
import pod.dsl.pick
import pod.dsl.survey.on
import pod.dsl.survey.pass
import pod.dsl.survey.surveyWorkflow
import pod.dsl.survey.task
import pod.dsl.then
import pod.samples.iSeed
import pod.samples.iSeedWorld
import pod.sim.SimFlavor
import kotlin.math.abs
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/** The survey workflow as a program's task, and the I-Seed sample that `pod survey` runs, in virtual time. */
class SurveyProgramSpec : StringSpec({

    "the I-Seed sample: the app sees ready, forward, paused, forward, backward, home, finished; photos detect what the simulator saw; only flagged waypoints are measured, 30 m above the ground; it lands at home" {
        virtualRun(seed = 23, timeout = 4.minutes) {
            val (result, record) = simulate(listOf(SimFlavor.ARDUCOPTER), configure = iSeedWorld(7)) { sim ->
                iSeed() to sim.simulated.single().photos.value
            }
            val (outcome, photos) = result
            val labels = outcome.phases.map { p ->
                when (p) {
                    is ControlPhase.Executing -> p.pass.name.lowercase()
                    is ControlPhase.Paused -> "paused"
                    else -> p::class.simpleName!!.lowercase()
                }
            }.fold(listOf<String>()) { acc, l -> if (acc.lastOrNull() == l) acc else acc + l }
            withClue(labels) {
                labels.filter { it != "waiting" && it != "pathbuilt" } shouldBe listOf("ready", "forward", "paused", "forward", "backward", "home", "finished")
            }
            val run = outcome.run
            run.forward.map { it.index } shouldBe outcome.plan.waypoints.indices.filter { outcome.plan.waypoints[it].photo }
            run.forward.map { it.result!!.value.sorted() } shouldBe photos.map { photo -> photo.detected.map { it.id }.sorted() }
            run.flagged.shouldNotBeEmpty()
            run.backward.map { it.first }.sorted() shouldBe run.flagged.sorted()
            // Measured from the altitude the forward pass corrected to: the survey's height above the ground.
            run.backward.forEach { (i, r) -> withClue("waypoint $i") { abs(r.result!!.meters - 30.0) shouldBeLessThan 4.0 } }
            record.tracks.values.single().second.last().let { last ->
                last.copy(altitude = outcome.home.altitude).distanceTo(outcome.home).meters shouldBeLessThan 3.0
            }
            outcome.vehicle.landedState.value shouldBe LandedState.ON_GROUND
        }
    }

    "surveyWorkflow is a task: after a mission on a picked vehicle it flies the area, fills its plan and result and lands; bound to two vehicles it fails typed" {
        virtualRun(seed = 24, timeout = 4.minutes) {
            val (result, record) = simulate(listOf(SimFlavor.ARDUCOPTER, SimFlavor.ARDUCOPTER)) {
                val picked = pick { count(2) }
                val a = picked[0]
                val b = picked[1]
                val home = a.home.value!!
                val field = listOf(0 to 0, 0 to 60, 50 to 60, 50 to 0).map { (n, e) -> home.offset((n + 20).m, (e - 30).m) }
                val survey = surveyWorkflow(field, 20.m, SurveySpacing.Direct(30.m), forward = { pass(takePhoto().index) }, backward = { }) { actionTimeout = 10.seconds }
                execute(mission("up") { home(home); takeOff(20.m) } on a then (survey on a))
                val twice = surveyWorkflow(field, 20.m, SurveySpacing.Direct(30.m), forward = { pass(Unit) }, backward = { })
                val refused = shouldThrow<SurveyNeedsOneVehicle> { execute(twice.task() on listOf(a, b)) }
                Triple(survey, refused.vehicles, a.landedState.value)
            }
            val (survey, vehicles, landed) = result
            vehicles shouldBe 2
            val plan = survey.plan.value!!
            val run = survey.result.value!!
            run.forward.size shouldBe plan.waypoints.count { it.photo }
            run.forward.map { it.result!!.value } shouldBe run.forward.indices.map { run.forward.first().result!!.value + it }
            run.backward shouldBe emptyList()
            landed shouldBe LandedState.ON_GROUND
            record.events.filterIsInstance<EngineEvent.TaskCompleted>().map { it.label } shouldContainAll listOf("survey")
        }
    }

    "surveyService after the program's own take-off: ready in the air, the operator's path started from there, an abort ends the task with SurveyAborted once the vehicle is home" {
        virtualRun(seed = 25, timeout = 4.minutes) {
            val (result, _) = simulate(listOf(SimFlavor.ARDUCOPTER)) {
                val v = pick { count(1) }[0]
                val home = v.home.value!!
                execute(mission("up") { home(home); takeOff(20.m) } on v)
                val control = MissionControl<SurveyPlan>()
                val service = surveyService(control, forward = { pass(Unit) }, backward = { })
                val operator = action("app") {
                    control.state.first { it.phase == ControlPhase.Ready }
                    val field = listOf(0 to 0, 0 to 60, 60 to 60, 60 to 0).map { (n, e) -> home.offset((n + 20).m, e.m) }
                    control.command(ControlCommand.Build(control.nextEventId(), PolygonSurvey.plan(field, 20.m, SurveySpacing.Direct(30.m), start = home, trigger = CameraTrigger.PER_WAYPOINT)))
                    control.command(ControlCommand.Start(control.nextEventId()))
                    control.state.first { ((it.phase as? ControlPhase.Executing)?.waypoint ?: 0) >= 2 }
                    control.command(ControlCommand.Abort(control.nextEventId()))
                }
                val failure = shouldThrow<SurveyAborted> { execute((service on v) and operator) }
                Triple(failure.reason, v.landedState.value, control.state.value.phase)
            }
            val (reason, landed, phase) = result
            reason shouldBe "aborted by the operator"
            landed shouldBe LandedState.ON_GROUND
            phase.shouldBeInstanceOf<ControlPhase.Aborted>()
        }
    }
})
