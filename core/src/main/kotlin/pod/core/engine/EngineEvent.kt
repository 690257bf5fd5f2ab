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

    /** A task started; [id] numbers tasks in the order they start, [parent] is its parent's id (0 for none). */
    public data class TaskStarted(override val at: Duration, val id: Int, val parent: Int, val label: String, val vehicles: List<Int>) : EngineEvent

    /** A task completed normally. */
    public data class TaskCompleted(override val at: Duration, val id: Int, val label: String) : EngineEvent

    /** A task failed with [error]. */
    public data class TaskFailed(override val at: Duration, val id: Int, val label: String, val error: Throwable) : EngineEvent

    /** A task was cancelled (its condition fired, its deadline passed, a sibling failed, the program stopped). */
    public data class TaskCancelled(override val at: Duration, val id: Int, val label: String) : EngineEvent

    /** Task [task] starts flying [mission] on [vehicle]. */
    public data class Flying(override val at: Duration, val task: Int, val vehicle: Int, val mission: pod.core.mission.Mission) : EngineEvent

    /** What a vehicle reported while task [task] flew it. */
    public data class Mission(override val at: Duration, val task: Int, val vehicle: Int, val event: MissionEvent) : EngineEvent

    /** What the queue that task [task] flies on [vehicle] did: an element started or ended, or it ran empty. */
    public data class Queue(override val at: Duration, val task: Int, val vehicle: Int, val event: pod.core.queue.QueueEvent) : EngineEvent

    /** A vehicle was put in [state] after its task was cancelled or failed; [confirmed] is false when the vehicle did not confirm. */
    public data class MadeSafe(override val at: Duration, val vehicle: Int, val state: SafeState, val confirmed: Boolean) : EngineEvent

    /** The program picked [vehicles]. */
    public data class Picked(override val at: Duration, val vehicles: List<Int>) : EngineEvent

    /** The program released [vehicles]. */
    public data class Released(override val at: Duration, val vehicles: List<Int>) : EngineEvent

    /** The program said [text] (Dolphin `message`). */
    public data class Message(override val at: Duration, val text: String) : EngineEvent

    /**
     * The code of program [program] ([Program.id]) is done, however it ended; the vehicles it still
     * holds are released right after ([Released]). A consumer that shows one program's run stops
     * here.
     */
    public data class ProgramEnded(override val at: Duration, val program: Int) : EngineEvent
}
