package pod.launch

import pod.core.engine.EngineEvent
import pod.core.platform.MissionEvent
import kotlin.time.Duration

/** Engine events as one line each, for people: "  03:12  copter-2  step 4 of 19 done". */
public class EventLines(private val names: (Int) -> String) {
    /** The line for [event], or null for events too fine to print (task starts of plain composites, a program's end). */
    public fun line(event: EngineEvent): String? {
        val text = when (event) {
            is EngineEvent.TaskStarted -> if (event.label.startsWith("slot") || event.label.contains(" on [")) "start  ${event.label}" else null
            is EngineEvent.TaskCompleted -> if (event.label.contains(" on [")) "done   ${event.label}" else null
            is EngineEvent.TaskFailed -> "FAILED ${event.label}: ${event.error.message}"
            is EngineEvent.TaskCancelled -> if (event.label.contains(" on [")) "cancel ${event.label}" else null
            is EngineEvent.Flying -> "${names(event.vehicle)} flies '${event.mission.name}' (${steps(event.mission.steps.size)})"
            is EngineEvent.Mission -> mission(names(event.vehicle), event.event)
            is EngineEvent.Queue -> queue(names(event.vehicle), event.event)
            is EngineEvent.MadeSafe -> "${names(event.vehicle)} made safe: ${event.state}${if (event.confirmed) "" else " (not confirmed)"}"
            is EngineEvent.Picked -> "picked ${event.vehicles.joinToString { names(it) }}"
            is EngineEvent.Released -> "released ${event.vehicles.joinToString { names(it) }}"
            is EngineEvent.Message -> "» ${event.text}"
            is EngineEvent.ProgramEnded -> null
        } ?: return null
        return "${clock(event.at)}  $text"
    }

    private fun mission(name: String, event: MissionEvent): String? = when (event) {
        is MissionEvent.Uploaded -> "$name mission on board (${steps(event.steps)})"
        is MissionEvent.Prepared -> "$name ready to fly: ${event.changes.joinToString(", ")}"
        MissionEvent.Started -> "$name started"
        is MissionEvent.StepStarted -> null
        is MissionEvent.StepDone -> "$name step ${event.step + 1} done"
        is MissionEvent.Loitering -> "$name loitering at step ${event.step + 1}, until the task is cancelled"
        MissionEvent.Completed -> "$name mission complete"
    }

    private fun queue(name: String, event: pod.core.queue.QueueEvent): String = when (event) {
        is pod.core.queue.QueueEvent.Started -> "$name queue: flying ${event.entry}"
        is pod.core.queue.QueueEvent.Ended -> "$name queue: ${event.entry} ended (${event.reason.name.lowercase()})"
        is pod.core.queue.QueueEvent.Emptied -> "$name queue: empty, holding"
    }

    /** The words and numbers event lines are made of, for other printers to reuse. */
    public companion object {
        /** "1 step", "4 steps". */
        public fun steps(count: Int): String = if (count == 1) "1 step" else "$count steps"

        /** mm:ss of vehicle time. */
        public fun clock(at: Duration): String {
            val s = at.inWholeSeconds
            return "%02d:%02d".format(s / 60, s % 60)
        }
    }
}
