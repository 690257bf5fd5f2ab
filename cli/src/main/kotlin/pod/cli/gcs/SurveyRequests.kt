package pod.cli.gcs

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import pod.cli.json.EventJson
import pod.core.workflow.ControlCommand

// The survey panel's requests: plan a path to look at, build it into the vehicle's mission control,
// then start, pause, resume or abort the flight (`survey_command`, the I-Seed operator's app). Each
// command answers with its event id, or with the app's reason for refusing it.

/**
 * `{"op":"survey_plan","id":1,"sysid":1,"area":{…}}`: plans a survey of [area] for vehicle
 * [sysid], entered nearest its home, without building it; the detail is the path as a
 * `survey_path` event (JSON) with event id 0. Bad areas are refused with the planner's reason.
 */
@Serializable @SerialName("survey_plan")
public data class SurveyPlanRequest(override val id: Long, val sysid: Int, val area: SurveyAreaJson) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String {
        val v = fleet.vehicle(sysid)
        return EventJson.encode(area.pathEvent(sysid, 0, area.plan(v)))
    }
}

/**
 * `survey_build`: plans [area] as [SurveyPlanRequest] does and builds it into vehicle [sysid]'s
 * mission control (its survey is set up on first use); the detail is the build's event id.
 */
@Serializable @SerialName("survey_build")
public data class SurveyBuild(override val id: Long, val sysid: Int, val area: SurveyAreaJson) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String {
        val v = fleet.vehicle(sysid)
        val plan = area.plan(v)
        return SurveyDesk.of(fleet).survey(sysid).build(area, plan).toString()
    }
}

/**
 * `{"op":"survey_command","id":2,"sysid":1,"command":"pause"}`: the operator's [command] to vehicle
 * [sysid]'s survey, which must have a path built; the detail is the command's event id, the error
 * the app's reason for refusing it (a pause while nothing flies, say).
 */
@Serializable @SerialName("survey_command")
public data class SurveyCommandRequest(override val id: Long, val sysid: Int, val command: SurveyCommandName) : GcsRequest {
    override suspend fun answer(fleet: GcsFleet): String {
        fleet.vehicle(sysid)
        return SurveyDesk.of(fleet).existing(sysid).command(command.word, command.make).toString()
    }
}

/** What the operator can tell a survey once its path is built, as [MissionControl][pod.core.workflow.MissionControl] takes it. */
@Serializable
public enum class SurveyCommandName(internal val word: String, internal val make: (Long) -> ControlCommand<Nothing>) {
    /** Fly the built path, taking off first when on the ground. */
    @SerialName("start") START("start", { ControlCommand.Start(it) }),

    /** Hold where it is, at its altitude. */
    @SerialName("pause") PAUSE("pause", { ControlCommand.Pause(it) }),

    /** Go on from where it paused. */
    @SerialName("resume") RESUME("resume", { ControlCommand.Resume(it) }),

    /** Stop: hold, then return home. */
    @SerialName("abort") ABORT("abort", { ControlCommand.Abort(it) }),

    /** Drop the built path. */
    @SerialName("cancel_path") CANCEL_PATH("cancel_path", { ControlCommand.CancelPath(it) }),
}
