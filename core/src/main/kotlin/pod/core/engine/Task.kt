package pod.core.engine

import pod.core.mission.Mission
import pod.core.platform.SafeState
import kotlin.time.Duration

/**
 * A task tree: what a program asks the fleet to do. A task is a value; running it
 * ([Program.execute]) is what takes time. pod-dsl builds these with Dolphin's operators
 * (`then`, `and`, `until`, `waitFor … then`, `allOf`, `oneOf`, `during`, `idle`, `watch`, `on`).
 */
public sealed class Task {
    /** A short name for events and logs. */
    public abstract val label: String

    /** Fly [mission] on every vehicle the task is bound to ([Bound]), each with its own executor. */
    public class Fly(
        /** The mission to fly. */
        public val mission: Mission,
        /** What a vehicle does when this task is cancelled mid-flight, or null for the program's choice. */
        public val onCancel: SafeState? = null,
    ) : Task() {
        override val label: String get() = mission.name
    }

    /**
     * Fly [queue] on the one vehicle the task is bound to: the vehicle flies the queue's current
     * element while the program (or other tasks) adds, replaces and skips elements. Completes when
     * the queue runs empty and [whenEmpty] is [pod.core.queue.WhenEmpty.COMPLETE], the vehicle holding where it is.
     */
    public class FlyQueue(
        /** The queue to fly. */
        public val queue: pod.core.queue.MissionQueue,
        /** What the task does when the queue runs empty. */
        public val whenEmpty: pod.core.queue.WhenEmpty = pod.core.queue.WhenEmpty.COMPLETE,
        /** What a vehicle does when this task is cancelled, or null for the program's choice. */
        public val onCancel: SafeState? = null,
    ) : Task() {
        override val label: String get() = "queue"
    }

    /**
     * Fly the survey workflow [job] on the one vehicle the task is bound to (a forward pass with an
     * action at every photo waypoint, a backward pass over the flagged ones, then home). Completes
     * when the vehicle is home ([pod.core.workflow.SurveyJob.result] then holds what it recorded).
     */
    public class Survey(
        /** The workflow to fly. */
        public val job: pod.core.workflow.SurveyJob<*, *>,
        /** What a vehicle does when this task is cancelled, or null for the program's choice. */
        public val onCancel: SafeState? = null,
    ) : Task() {
        override val label: String get() = "survey"
    }

    /** Run [tasks] one after the other; the first failure ends the sequence (Dolphin `>>`). */
    public class Sequence(
        /** The tasks in order. */
        public val tasks: List<Task>,
    ) : Task() {
        override val label: String get() = "sequence"
    }

    /** Run [tasks] at once; done when all are done; one failure cancels the others (Dolphin `|`). */
    public class Concurrent(
        /** The tasks to run together. */
        public val tasks: List<Task>,
    ) : Task() {
        override val label: String get() = "concurrently"
    }

    /** Run [task] until [condition] holds, then cancel it and complete (Dolphin `until`). */
    public class Until(
        /** The task to run. */
        public val task: Task,
        /** When to stop it. */
        public val condition: Condition,
    ) : Task() {
        override val label: String get() = "until"
    }

    /** Wait until [condition] holds, then run [task] (Dolphin `waitFor … then`). */
    public class WaitFor(
        /** What to wait for. */
        public val condition: Condition,
        /** What to run then. */
        public val task: Task,
    ) : Task() {
        override val label: String get() = "waitFor"
    }

    /** Every branch waits for its condition and then runs its task; done when all are (Dolphin `allOf`). */
    public class AllOf(
        /** The when-then branches. */
        public val branches: List<Branch>,
    ) : Task() {
        init {
            require(branches.isNotEmpty()) { "allOf: give at least one branch" }
        }

        override val label: String get() = "allOf"
    }

    /** Runs the first branch whose condition holds (ties go to the earlier branch) and ignores the rest (Dolphin `oneOf`). */
    public class OneOf(
        /** The when-then branches. */
        public val branches: List<Branch>,
    ) : Task() {
        init {
            require(branches.isNotEmpty()) { "oneOf: give at least one branch" }
        }

        override val label: String get() = "oneOf"
    }

    /** Run [task] for at most [limit]; when the limit passes it is cancelled and this completes (Dolphin `during`). */
    public class During(
        /** The time limit, in vehicle time (divided by the platform's time scale). */
        public val limit: Duration,
        /** The task to run. */
        public val task: Task,
    ) : Task() {
        override val label: String get() = "during $limit"
    }

    /** Do nothing for [time] (Dolphin `idle`). */
    public class Idle(
        /** How long, in vehicle time. */
        public val time: Duration,
    ) : Task() {
        override val label: String get() = "idle $time"
    }

    /** Run [task] and handle its failure by [onError] (Dolphin `watch … onError`). */
    public class Watch(
        /** The task to run. */
        public val task: Task,
        /** What a failure turns into. */
        public val onError: ErrorHandler,
    ) : Task() {
        override val label: String get() = "watch"
    }

    /** Run program code as a task: pick, release, message, compute (Dolphin `action { }`). */
    public class Action(
        /** A name for events. */
        override val label: String,
        /** The code to run, with the program as receiver; tasks it executes become this task's children. */
        public val block: suspend Program.() -> Unit,
    ) : Task()

    /** Run [task] on [vehicles]: every [Fly] inside it flies on each of them (Dolphin `task @ vehicles`). */
    public class Bound(
        /** The task to run; its missions fly on each of [vehicles]. */
        public val task: Task,
        /** The vehicles it runs on. */
        public val vehicles: VehicleSet,
    ) : Task() {
        override val label: String get() = "${task.label} on $vehicles"
    }
}

/** One `when … then …` branch of [Task.AllOf] or [Task.OneOf]. */
public class Branch(
    /** When the branch fires. */
    public val condition: Condition,
    /** What it runs. */
    public val task: Task,
)

/** What [Task.Watch] does with a failure of the task it watches. */
public sealed interface ErrorHandler {
    /** Swallow the failure: the watch completes normally (Dolphin `ignore`). */
    public data object Ignore : ErrorHandler

    /** Let the failure go up to the enclosing task (Dolphin `propagate`). */
    public data object Propagate : ErrorHandler

    /** Run the task [recover] returns for the failure instead. */
    public class Recover(
        /** Chooses the recovery task. */
        public val recover: (Throwable) -> Task,
    ) : ErrorHandler
}
