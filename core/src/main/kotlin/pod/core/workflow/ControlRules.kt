package pod.core.workflow

import pod.core.workflow.ControlCommand.Abort
import pod.core.workflow.ControlCommand.Build
import pod.core.workflow.ControlCommand.CancelPath
import pod.core.workflow.ControlCommand.Pause
import pod.core.workflow.ControlCommand.Resume
import pod.core.workflow.ControlCommand.Start
import pod.core.workflow.ControlPhase.Aborted
import pod.core.workflow.ControlPhase.Executing
import pod.core.workflow.ControlPhase.Finished
import pod.core.workflow.ControlPhase.Paused
import pod.core.workflow.ControlPhase.PathBuilt
import pod.core.workflow.ControlPhase.Ready
import pod.core.workflow.ControlPhase.Waiting

/** The transitions of [MissionControl], as pure functions (property-tested in MissionControlPropertyTest). */
public object ControlRules {
    /** [state] after the operator's [command], or why the command is refused. */
    public fun <P> apply(state: ControlState<P>, command: ControlCommand<P>): CommandOutcome<P> {
        if (command.eventId <= state.eventId) return CommandOutcome.Refused("event id ${command.eventId} is not newer than ${state.eventId}")
        val phase = state.phase
        fun to(next: ControlPhase, plan: P? = state.plan) = CommandOutcome.Accepted(ControlState(next, plan, command.eventId))
        fun refuse(what: String) = CommandOutcome.Refused("$what: not possible while ${describe(phase)}")
        return when (command) {
            is Build -> when (phase) {
                Ready, PathBuilt, Finished, is Aborted -> to(PathBuilt, command.plan)
                else -> refuse("build")
            }
            is CancelPath -> if (phase == PathBuilt) to(Ready, null) else refuse("cancel the path")
            is Start -> if (phase == PathBuilt) to(Executing(Pass.FORWARD)) else refuse("start")
            is Pause -> if (phase is Executing) to(Paused(phase.pass, phase.waypoint)) else refuse("pause")
            is Resume -> if (phase is Paused) to(Executing(phase.pass, phase.waypoint)) else refuse("resume")
            is Abort -> if (phase is Executing || phase is Paused) to(Aborted("aborted by the operator")) else refuse("abort")
        }
    }

    /**
     * [state] after the flight's [report], or null when the report is older than the latest
     * command (its event id is smaller than the state's) and so must not show.
     */
    public fun <P> report(state: ControlState<P>, report: ControlReport): ControlState<P>? {
        if (report.eventId < state.eventId) return null
        val phase = when (report) {
            is ControlReport.Vehicle -> when (state.phase) {
                Waiting, Ready -> if (report.ready) Ready else Waiting
                else -> return null // a built path or a flight outranks the vehicle's readiness
            }
            is ControlReport.Flying -> Executing(report.pass, report.waypoint)
            is ControlReport.Holding -> Paused(report.pass, report.waypoint)
            is ControlReport.Done -> Finished
            is ControlReport.Stopped -> Aborted(report.reason)
        }
        return ControlState(phase, state.plan, report.eventId)
    }

    private fun describe(phase: ControlPhase): String = when (phase) {
        Waiting -> "waiting for a vehicle"
        Ready -> "ready with no path"
        PathBuilt -> "a path is built"
        is Executing -> "executing the ${phase.pass.name.lowercase()} pass"
        is Paused -> "paused"
        Finished -> "finished"
        is Aborted -> "aborted"
    }
}
