package pod.core.engine

import pod.core.platform.MissionEvent
import pod.core.platform.SafeState
import kotlin.time.Duration

/**
 * Something that happened in a running program, in the order it happened. [at] is the time since
 * the [Engine] was made, in vehicle time (wall time × the platform's time scale).
 */
public sealed interface EngineEvent {
    /** When, since the engine was made, in vehicle time. */
    public val at: Duration

    /**
     * A task started.
     *
     * @property id numbers the engine's tasks in the order they start, from 1; later events about the task carry it.
     * @property parent the id of the task whose code started this one, 0 for a task the program's code started directly.
     * @property label a short name: the mission's name for a flight, else the kind of task (`queue`, `survey`, `sequence`, `until`, …).
     * @property vehicles the ids ([pod.core.platform.PlatformVehicle.id]) of the vehicles the task is bound to; empty when it is not bound.
     */
    public data class TaskStarted(override val at: Duration, val id: Int, val parent: Int, val label: String, val vehicles: List<Int>) : EngineEvent

    /**
     * A task completed normally.
     *
     * @property id the task's id from its [TaskStarted].
     * @property label the task's label from its [TaskStarted].
     */
    public data class TaskCompleted(override val at: Duration, val id: Int, val label: String) : EngineEvent

    /**
     * A task failed with [error].
     *
     * @property id the task's id from its [TaskStarted].
     * @property label the task's label from its [TaskStarted].
     * @property error what it failed with: a [pod.core.PodException] for Pod's own failures.
     */
    public data class TaskFailed(override val at: Duration, val id: Int, val label: String, val error: Throwable) : EngineEvent

    /**
     * A task was cancelled (its condition fired, its deadline passed, a sibling failed, the program stopped).
     *
     * @property id the task's id from its [TaskStarted].
     * @property label the task's label from its [TaskStarted].
     */
    public data class TaskCancelled(override val at: Duration, val id: Int, val label: String) : EngineEvent

    /**
     * Task [task] starts flying [mission] on [vehicle].
     *
     * @property task the id of the task that flies it.
     * @property vehicle the id of the vehicle.
     * @property mission the mission it flies, as the program built it.
     */
    public data class Flying(override val at: Duration, val task: Int, val vehicle: Int, val mission: pod.core.mission.Mission) : EngineEvent

    /**
     * What a vehicle reported while task [task] flew it.
     *
     * @property task the id of the task that flies the mission.
     * @property vehicle the id of the vehicle that reported.
     * @property event the report: uploaded, step started or done, loitering, ….
     */
    public data class Mission(override val at: Duration, val task: Int, val vehicle: Int, val event: MissionEvent) : EngineEvent

    /**
     * What the queue that task [task] flies on [vehicle] did: an element started or ended, or it ran empty.
     *
     * @property task the id of the task that flies the queue.
     * @property vehicle the id of the vehicle flying it.
     * @property event what the queue did.
     */
    public data class Queue(override val at: Duration, val task: Int, val vehicle: Int, val event: pod.core.queue.QueueEvent) : EngineEvent

    /**
     * A vehicle was put in a safe state after its task was cancelled or failed.
     *
     * @property vehicle the id of the vehicle.
     * @property state the safe state it was asked for: hold or return home.
     * @property confirmed false when the vehicle was lost, refused, or did not confirm within [EngineConfig.safeTimeout].
     */
    public data class MadeSafe(override val at: Duration, val vehicle: Int, val state: SafeState, val confirmed: Boolean) : EngineEvent

    /**
     * The program picked [vehicles].
     *
     * @property vehicles the ids of the vehicles picked.
     */
    public data class Picked(override val at: Duration, val vehicles: List<Int>) : EngineEvent

    /**
     * The program released [vehicles].
     *
     * @property vehicles the system ids of the vehicles released.
     */
    public data class Released(override val at: Duration, val vehicles: List<Int>) : EngineEvent

    /**
     * The program said [text] (Dolphin `message`).
     *
     * @property text what the program said.
     */
    public data class Message(override val at: Duration, val text: String) : EngineEvent

    /**
     * The code of program [program] ([Program.id]) is done, however it ended; the vehicles it still
     * holds are released right after ([Released]). A consumer that shows one program's run stops
     * here.
     *
     * @property program the id of the program that ended.
     */
    public data class ProgramEnded(override val at: Duration, val program: Int) : EngineEvent
}
