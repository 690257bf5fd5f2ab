package pod.test

import io.kotest.core.spec.style.StringSpec
import io.kotest.matchers.doubles.shouldBeLessThan
import io.kotest.matchers.should
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.checkAll
import kotlinx.coroutines.flow.first
import pod.core.survey.CameraTrigger
import pod.core.survey.PolygonSurvey
import pod.core.survey.SurveyPlan
import pod.core.survey.SurveySpacing
import pod.core.units.m
import pod.core.workflow.CommandOutcome
import pod.core.workflow.ControlCommand
import pod.core.workflow.ControlPhase
import pod.core.workflow.MissionControl
import pod.dsl.action
import pod.dsl.and
import pod.dsl.idle
import pod.dsl.pick
import pod.dsl.survey.on
import pod.dsl.survey.pass
import pod.dsl.survey.surveyService
import pod.sim.SimVehicleConfig
import pod.test.landWithin
import pod.test.polygon
import pod.test.virtualFleet
import kotlin.time.Duration.Companion.seconds

class SurveyPropertySpec : StringSpec({
    "for any polygon and any pause times, the survey photographs every waypoint and lands at home" {
        val fieldCenter = SimVehicleConfig.DEFAULT_HOME.offset(north = 70.m, east = 70.m)
        val polygons = Arb.polygon(fieldCenter, radius = 20.m..45.m, corners = 3..7)
        val pauseTimes = Arb.list(Arb.int(5..60), 0..3) // seconds of flight before each 15 s pause
        checkAll(PropTestConfig(iterations = 8, seed = 29), polygons, pauseTimes) { field, pauses ->
            val record = virtualFleet(seed = 29) { copters(1) }.run {
                val drone = pick { count(1) }[0]
                val control = MissionControl<SurveyPlan>()
                val survey = surveyService(control, forward = { pass(takePhoto().index) }, backward = { })
                val operator = action("operator") {
                    control.state.first { it.phase == ControlPhase.Ready }
                    val plan = PolygonSurvey.plan(field, 20.m, SurveySpacing.Direct(20.m), start = drone.home.value, trigger = CameraTrigger.PER_WAYPOINT)
                    control.command(ControlCommand.Build(control.nextEventId(), plan))
                    control.command(ControlCommand.Start(control.nextEventId()))
                    for (at in pauses) {
                        execute(idle(at.seconds))
                        if (control.command(ControlCommand.Pause(control.nextEventId())) is CommandOutcome.Accepted) {
                            execute(idle(15.seconds))
                            control.command(ControlCommand.Resume(control.nextEventId()))
                        }
                    }
                }
                execute((survey on drone) and operator)
                control.state.value.plan!!
            }
            val waypoints = record.result.waypoints.filter { it.photo }
            val photos = record.photos.getValue(1)
            photos.size shouldBe waypoints.size
            waypoints.zip(photos).forEach { (waypoint, photo) ->
                photo.location.distanceTo(waypoint.location.copy(altitude = photo.location.altitude)).meters shouldBeLessThan 3.0
            }
            record.track(1) should landWithin(3.m, of = record.track(1).home)
        }
    }
})
