package pod.dsl.survey

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import pod.core.engine.Task
import pod.core.survey.SurveyPlan
import pod.core.survey.SurveySpacing
import pod.core.units.Location
import pod.core.units.m
import pod.core.workflow.MissionControl
import pod.core.workflow.OnFailure
import kotlin.time.Duration.Companion.seconds

class SurveyWorkflowsTest : FunSpec({
    val origin = Location(41.0, -8.0, 0.m)
    val square = listOf(0 to 0, 0 to 100, 100 to 100, 100 to 0).map { (n, e) -> origin.offset(n.m, e.m) }

    test("a survey workflow takes its options and plans its area when the vehicle is known, entered nearest it") {
        val job = surveyWorkflow(square, 30.m, SurveySpacing.Direct(25.m), forward = { pass(index) }, backward = { index }) {
            actionTimeout = 12.seconds
            onFailure = retry(2)
            correctAltitude(target = 30.m, minimum = 10.m)
        }
        job.settings.actionTimeout shouldBe 12.seconds
        job.settings.onFailure shouldBe OnFailure.Retry(2)
        job.settings.altitudeCorrection!!.minimum shouldBe 10.m
        job.control shouldBe null
        val farCorner = origin.offset(100.m, 100.m)
        val plan = job.area!!.plan(farCorner)
        plan.waypoints.first().location.distanceTo(farCorner.copy(altitude = 30.m)).meters.let { (it < 20.0) shouldBe true }
        plan.waypoints.all { it.photo || it.transit || it.turnaround } shouldBe true
        job.task().shouldBeInstanceOf<Task.Survey>()
    }

    test("bad arguments fail when the workflow is built, naming what is wrong") {
        shouldThrow<IllegalArgumentException> { surveyWorkflow(square.take(2), 30.m, SurveySpacing.Direct(25.m), forward = { pass(Unit) }, backward = { }) }
            .message shouldContain "at least 3 points"
        shouldThrow<IllegalArgumentException> { surveyWorkflow(square, 30.m, SurveySpacing.Direct(0.m), forward = { pass(Unit) }, backward = { }) }
            .message shouldContain "spacing"
        val bowTie = listOf(origin, origin.offset(100.m, 100.m), origin.offset(0.m, 100.m), origin.offset(100.m, 0.m))
        shouldThrow<IllegalArgumentException> { surveyWorkflow(bowTie, 30.m, SurveySpacing.Direct(25.m), forward = { pass(Unit) }, backward = { }) }
            .message shouldContain "intersect"
        shouldThrow<IllegalArgumentException> { surveyWorkflow(square, 30.m, SurveySpacing.Direct(25.m), forward = { pass(Unit) }, backward = { }) { actionTimeout = 0.seconds } }
            .message shouldContain "actionTimeout"
        shouldThrow<IllegalArgumentException> { surveyWorkflow(square, 30.m, SurveySpacing.Direct(25.m), forward = { pass(Unit) }, backward = { }) { onFailure = retry(0) } }
            .message shouldContain "times"
    }

    test("a survey service serves a mission control and has no area of its own") {
        val control = MissionControl<SurveyPlan>()
        val job = surveyService(control, forward = { flag(index) }, backward = { })
        job.control shouldBe control
        job.area shouldBe null
    }
})
