package pod.core.workflow

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow

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

    /** What the app shows. */
    public val state: StateFlow<ControlState<P>> = _state.asStateFlow()

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
            if (_state.compareAndSet(current, outcome.state)) return outcome
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
}
