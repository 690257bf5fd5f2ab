package pod.core.engine

import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.StateFlow
import pod.core.engine.FakeFleet.Companion.mission
import kotlin.random.Random
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * A generated task tree as plain data, so a failing case prints readably; [build] turns it into a
 * [Task] over a fleet. Every condition also holds once the program clock reaches [Cond.at], so
 * every tree ends by itself, within [bound].
 */
internal sealed interface TaskPlan {
    /** `Bound(Fly(mission), vehicles)`; a mission named "fail…" fails after its first step. */
    data class Fly(val name: String, val vehicles: List<Int>, val steps: Int) : TaskPlan {
        override fun toString() = "fly($name×$steps on $vehicles)"
    }

    data class Seq(val tasks: List<TaskPlan>) : TaskPlan {
        override fun toString() = tasks.joinToString(" >> ", "(", ")")
    }

    data class Conc(val tasks: List<TaskPlan>) : TaskPlan {
        override fun toString() = tasks.joinToString(" | ", "(", ")")
    }

    data class Until(val task: TaskPlan, val cond: Cond) : TaskPlan {
        override fun toString() = "($task until $cond)"
    }

    data class WaitFor(val cond: Cond, val task: TaskPlan) : TaskPlan {
        override fun toString() = "waitFor($cond) then $task"
    }

    data class AllOf(val branches: List<Pair<Cond, TaskPlan>>) : TaskPlan {
        override fun toString() = branches.joinToString("; ", "allOf{", "}") { (c, t) -> "when $c then $t" }
    }

    data class OneOf(val branches: List<Pair<Cond, TaskPlan>>) : TaskPlan {
        override fun toString() = branches.joinToString("; ", "oneOf{", "}") { (c, t) -> "when $c then $t" }
    }

    data class During(val limit: Duration, val task: TaskPlan) : TaskPlan {
        override fun toString() = "during($limit){$task}"
    }

    data class Idle(val time: Duration) : TaskPlan {
        override fun toString() = "idle($time)"
    }

    /** [recover] null with [propagate] false is `ignore`. */
    data class Watch(val task: TaskPlan, val propagate: Boolean, val recover: TaskPlan?) : TaskPlan {
        override fun toString() = "watch($task) onError " + (recover?.let { "recover $it" } ?: if (propagate) "propagate" else "ignore")
    }

    /** An action that picks [count] vehicles (giving up after [timeout]), holds them for [hold] and releases them when [release]. */
    data class Pick(val count: Int, val hold: Duration, val release: Boolean, val timeout: Duration) : TaskPlan {
        override fun toString() = "pick($count, hold $hold${if (release) ", release" else ""})"
    }

    data class Message(val text: String) : TaskPlan {
        override fun toString() = "message($text)"
    }
}

/** Holds when the battery of [vehicle] is below [below], or once the program clock reaches [at]. */
internal data class Cond(val vehicle: Int?, val below: Double, val at: Duration) {
    override fun toString() = (if (vehicle != null) "battery($vehicle)<$below or " else "") + "clock≥$at"

    fun condition(fleet: FakeFleet, clock: StateFlow<Duration>): Condition = Condition {
        (vehicle != null && battery(fleet[vehicle]) < below) || read(clock) >= at
    }
}

/** How long a fake vehicle takes to confirm its safe state. */
internal val SAFE_TIME = 1.seconds

/** How long a fake vehicle takes per mission step. */
internal val STEP_TIME = 10.seconds

/**
 * An upper bound on how long [plan] runs from its start, however it ends. Cancellation and failure
 * cost up to [SAFE_TIME] per level they travel up (each level's siblings are made safe in turn).
 */
internal fun bound(plan: TaskPlan): Duration = when (plan) {
    is TaskPlan.Fly -> STEP_TIME * (if (plan.name.startsWith("fail")) 1 else plan.steps) + SAFE_TIME * 2
    is TaskPlan.Seq -> plan.tasks.fold(Duration.ZERO) { sum, t -> sum + bound(t) }
    is TaskPlan.Conc -> plan.tasks.maxOf { bound(it) } + SAFE_TIME
    // The condition holds by clock time `at` at the latest; then the task is cancelled and made safe.
    is TaskPlan.Until -> minOf(bound(plan.task), plan.cond.at + SAFE_TIME)
    is TaskPlan.WaitFor -> plan.cond.at + bound(plan.task)
    is TaskPlan.AllOf -> plan.branches.maxOf { (c, t) -> c.at + bound(t) } + SAFE_TIME
    is TaskPlan.OneOf -> plan.branches.minOf { it.first.at } + plan.branches.maxOf { bound(it.second) }
    is TaskPlan.During -> minOf(bound(plan.task), plan.limit + SAFE_TIME)
    is TaskPlan.Idle -> plan.time
    is TaskPlan.Watch -> bound(plan.task) + (plan.recover?.let { bound(it) } ?: Duration.ZERO)
    is TaskPlan.Pick -> plan.timeout + plan.hold
    is TaskPlan.Message -> Duration.ZERO
}

/** Every clock time a condition in [plan] waits for. */
internal fun clockTimes(plan: TaskPlan): Set<Duration> = when (plan) {
    is TaskPlan.Seq -> plan.tasks.flatMapTo(HashSet()) { clockTimes(it) }
    is TaskPlan.Conc -> plan.tasks.flatMapTo(HashSet()) { clockTimes(it) }
    is TaskPlan.Until -> clockTimes(plan.task) + plan.cond.at
    is TaskPlan.WaitFor -> clockTimes(plan.task) + plan.cond.at
    is TaskPlan.AllOf -> plan.branches.flatMapTo(HashSet()) { (c, t) -> clockTimes(t) + c.at }
    is TaskPlan.OneOf -> plan.branches.flatMapTo(HashSet()) { (c, t) -> clockTimes(t) + c.at }
    is TaskPlan.During -> clockTimes(plan.task)
    is TaskPlan.Watch -> clockTimes(plan.task) + (plan.recover?.let { clockTimes(it) } ?: emptySet())
    is TaskPlan.Fly, is TaskPlan.Idle, is TaskPlan.Pick, is TaskPlan.Message -> emptySet()
}

/** The task [plan] describes, over [fleet]; conditions read [clock] as the program's time. */
internal fun build(plan: TaskPlan, fleet: FakeFleet, clock: StateFlow<Duration>): Task {
    fun TaskPlan.task(): Task = build(this, fleet, clock)
    fun Cond.condition() = condition(fleet, clock)
    return when (plan) {
        is TaskPlan.Fly -> Task.Bound(Task.Fly(mission(plan.name, plan.steps)), VehicleSet(plan.vehicles.map { fleet[it] }))
        is TaskPlan.Seq -> Task.Sequence(plan.tasks.map { it.task() })
        is TaskPlan.Conc -> Task.Concurrent(plan.tasks.map { it.task() })
        is TaskPlan.Until -> Task.Until(plan.task.task(), plan.cond.condition())
        is TaskPlan.WaitFor -> Task.WaitFor(plan.cond.condition(), plan.task.task())
        is TaskPlan.AllOf -> Task.AllOf(plan.branches.map { (c, t) -> Branch(c.condition(), t.task()) })
        is TaskPlan.OneOf -> Task.OneOf(plan.branches.map { (c, t) -> Branch(c.condition(), t.task()) })
        is TaskPlan.During -> Task.During(plan.limit, plan.task.task())
        is TaskPlan.Idle -> Task.Idle(plan.time)
        is TaskPlan.Watch -> Task.Watch(
            plan.task.task(),
            when {
                plan.recover != null -> plan.recover.let { recovery -> ErrorHandler.Recover { recovery.task() } }
                plan.propagate -> ErrorHandler.Propagate
                else -> ErrorHandler.Ignore
            },
        )
        is TaskPlan.Pick -> Task.Action("pick ${plan.count}") {
            val got = pick(PickRequest(count = plan.count, timeout = plan.timeout))
            delay(plan.hold)
            if (plan.release) release(got)
        }
        is TaskPlan.Message -> Task.Action("say ${plan.text}") { message(plan.text) }
    }
}

/** Random task trees of depth ≤ [maxDepth] over vehicles 1..[vehicles]; mission names carry [tag]. */
internal class TaskPlanGenerator(private val random: Random, private val vehicles: Int, private val tag: String, private val maxDepth: Int = 4) {
    private var names = 0

    fun plan(depth: Int = 0): TaskPlan {
        if (depth >= maxDepth || random.nextInt(10) < 2 + depth) return leaf()
        fun children() = List(random.nextInt(1, 4)) { plan(depth + 1) }
        fun branches() = List(random.nextInt(1, 4)) { cond() to plan(depth + 1) }
        return when (random.nextInt(9)) {
            0 -> TaskPlan.Seq(children())
            1 -> TaskPlan.Conc(children())
            2 -> TaskPlan.Until(plan(depth + 1), cond())
            3 -> TaskPlan.WaitFor(cond(), plan(depth + 1))
            4 -> TaskPlan.AllOf(branches())
            5 -> TaskPlan.OneOf(branches())
            6 -> TaskPlan.During(random.nextInt(1, 60).seconds + (random.nextInt(4) * 250).milliseconds, plan(depth + 1))
            else -> TaskPlan.Watch(
                plan(depth + 1),
                propagate = random.nextBoolean(),
                recover = if (random.nextInt(3) == 0) plan(depth + 1) else null,
            )
        }
    }

    private fun leaf(): TaskPlan = when (random.nextInt(10)) {
        0 -> TaskPlan.Idle(random.nextInt(0, 30).seconds)
        1 -> TaskPlan.Pick(
            count = random.nextInt(1, minOf(vehicles, 2) + 1),
            hold = random.nextInt(0, 20).seconds,
            release = random.nextBoolean(),
            timeout = random.nextInt(1, 30).seconds,
        )
        2 -> TaskPlan.Message("m${names++}")
        else -> {
            val on = (1..vehicles).shuffled(random).take(if (random.nextInt(4) == 0) 2 else 1).sorted()
            val name = (if (random.nextInt(5) == 0) "fail-" else "m-") + tag + names++
            TaskPlan.Fly(name, on, random.nextInt(1, 7))
        }
    }

    private fun cond(): Cond = Cond(
        vehicle = if (random.nextBoolean()) random.nextInt(1, vehicles + 1) else null,
        below = listOf(0.5, 0.7, 0.85, 0.95).random(random),
        at = if (random.nextInt(5) == 0) Duration.ZERO else random.nextInt(1, 120).seconds,
    )
}
