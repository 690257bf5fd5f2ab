package pod.core.workflow

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update

/**
 * What an operator's app shows of a survey workflow and sends to it, as the I-Seed service's mission
 * control does: a state machine of the states an operator sees ([ControlPhase]), driven by the
 * operator's [ControlCommand]s and by the flight's [ControlReport]s, published as a [StateFlow]
 * an Android or desktop app binds to.
 *
 * Every command carries an event id that grows with each command; the state takes it at once (the
 * app shows "paused" when the operator presses pause), and a report counts only when it was made
 * after the flight had applied the latest command (its event id is at least the state's). So a
 * report still in flight from before a pause — "executing, waypoint 7" — cannot flip the app back
 * to executing while the pause travels. Commands the current state does not allow are refused with
 * a reason and change nothing. Thread-safe; [P] is what a built path is (a survey plan).
 *
 * A controller attached to a vehicle that is already flying (the app restarted) starts from the
 * phase the flight reports ([initial]) instead of assuming [ControlPhase.Ready].
 */
public class MissionControl<P>(initial: ControlState<P> = ControlState(ControlPhase.Waiting, null, 0)) {
    private val _state = MutableStateFlow(initial)
    private val issued = MutableStateFlow(initial.eventId)
    private val _intent = MutableStateFlow(ControlIntent(initial, 0))

    /** What the app shows. */
    public val state: StateFlow<ControlState<P>> = _state.asStateFlow()

    /**
     * What the operator asked for last: the state right after the latest accepted command (not
     * moved by reports) and which start it belongs to. The flight side follows it (pause when it
     * says paused, abort when aborted) and stamps its reports with its event id.
     */
    public val intent: StateFlow<ControlIntent<P>> = _intent.asStateFlow()

    /** The event id for the operator's next command: one more than any issued or seen so far. */
    public fun nextEventId(): Long {
        while (true) {
            val seen = issued.value
            val next = maxOf(seen, _state.value.eventId) + 1
            if (issued.compareAndSet(seen, next)) return next
        }
    }

    /** Applies the operator's [command]: the new state, or why it is refused (nothing changes then). */
    public fun command(command: ControlCommand<P>): CommandOutcome<P> {
        while (true) {
            val current = _state.value
            val outcome = ControlRules.apply(current, command)
            if (outcome !is CommandOutcome.Accepted) return outcome
            if (_state.compareAndSet(current, outcome.state)) {
                _intent.update {
                    if (it.state.eventId >= outcome.state.eventId) it
                    else ControlIntent(outcome.state, if (command is ControlCommand.Start) command.eventId else it.startedBy)
                }
                return outcome
            }
        }
    }

    /** Takes the flight's [report]; true when it counted, false when it was older than the last command. */
    public fun report(report: ControlReport): Boolean {
        while (true) {
            val current = _state.value
            val next = ControlRules.report(current, report) ?: return false
            if (_state.compareAndSet(current, next)) return true
        }
    }

    /** Ways to make a controller other than from scratch. */
    public companion object {
        /**
         * A controller for an app that (re)attaches to a flight already under way: it starts from
         * what the flight last reported ([latest], with the event id it carries) and the [plan]
         * being flown, instead of assuming a vehicle ready for a new path.
         */
        public fun <P> attachedTo(latest: ControlReport, plan: P? = null): MissionControl<P> {
            val start = ControlState<P>(ControlPhase.Waiting, plan, 0)
            return MissionControl(ControlRules.report(start, latest) ?: start)
        }
    }
}
