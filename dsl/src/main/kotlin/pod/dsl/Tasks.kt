package pod.dsl

import pod.core.engine.Branch
import pod.core.engine.Condition
import pod.core.engine.ConditionScope
import pod.core.engine.ErrorHandler
import pod.core.engine.Program
import pod.core.engine.Task
import pod.core.engine.VehicleSet
import pod.core.engine.asSet
import pod.core.mission.Mission
import pod.core.platform.PlatformVehicle
import pod.core.platform.SafeState
import kotlin.time.Duration

// Dolphin's operators as Kotlin infix functions. Kotlin gives every infix function the same
// precedence, evaluated left to right, so `a then b and c` is `(a then b) and c`: use parentheses.

/** Run this, then [next] (Dolphin `a >> b`). */
public infix fun Task.then(next: Task): Task = Task.Sequence(flatten<Task.Sequence>(this) { it.tasks } + flatten<Task.Sequence>(next) { it.tasks })

/** Run this and [other] at once; done when both are (Dolphin `a | b`). */
public infix fun Task.and(other: Task): Task = Task.Concurrent(flatten<Task.Concurrent>(this) { it.tasks } + flatten<Task.Concurrent>(other) { it.tasks })

/** Run [tasks] one after the other (Dolphin `a >> b >> c`). */
public fun sequence(vararg tasks: Task): Task = Task.Sequence(tasks.toList())

/** Run [tasks] at once (Dolphin `a | b | c`). */
public fun concurrently(vararg tasks: Task): Task = Task.Concurrent(tasks.toList())

/** Run [tasks] at once (Dolphin `a | b | c`). */
public fun concurrently(tasks: Iterable<Task>): Task = Task.Concurrent(tasks.toList())

/** Run this until [condition] holds, then cancel it, making its vehicles safe (Dolphin `t until c`). */
public infix fun Task.until(condition: ConditionScope.() -> Boolean): Task = Task.Until(this, condition(condition))

/** Run this until [condition] holds (Dolphin `t until c`). */
public infix fun Task.until(condition: Condition): Task = Task.Until(this, condition)

/** Run this for at most [limit] of vehicle time, then cancel it and go on (Dolphin `during(limit) { t }`). */
public infix fun Task.during(limit: Duration): Task = Task.During(limit, this)

/** Do nothing for [time] of vehicle time (Dolphin `idle(time)`). */
public fun idle(time: Duration): Task = Task.Idle(time)

/** Fly this mission on [vehicles], each with its own executor (Dolphin `task @ vehicles`). */
public infix fun Mission.on(vehicles: Iterable<PlatformVehicle>): Task = Task.Bound(Task.Fly(this), VehicleSet(vehicles))

/** Fly this mission on [vehicle] (Dolphin `task @ vehicle`). */
public infix fun Mission.on(vehicle: PlatformVehicle): Task = Task.Bound(Task.Fly(this), vehicle.asSet())

/** Run this task on [vehicles]: every mission inside it flies on each of them (Dolphin `task @ vehicles`). */
public infix fun Task.on(vehicles: Iterable<PlatformVehicle>): Task = Task.Bound(this, VehicleSet(vehicles))

/** Run this task on [vehicle] (Dolphin `task @ vehicle`). */
public infix fun Task.on(vehicle: PlatformVehicle): Task = Task.Bound(this, vehicle.asSet())

/** The set of these two vehicles (Dolphin's vehicle-set `+`). */
public operator fun PlatformVehicle.plus(other: PlatformVehicle): VehicleSet = VehicleSet(listOf(this, other))

/** This mission as a task still to be bound with [on]; when cancelled, its vehicles do [onCancel]. */
public fun Mission.task(onCancel: SafeState? = null): Task = Task.Fly(this, onCancel)

/** Fly this mission on [vehicles]; when cancelled they return home instead of holding. */
public infix fun Mission.returningOn(vehicles: Iterable<PlatformVehicle>): Task =
    Task.Bound(Task.Fly(this, SafeState.RETURN_HOME), VehicleSet(vehicles))

/** A condition over live telemetry, such as `condition { battery(v) < 0.3 }` (Dolphin `condition { }`). */
public fun condition(holds: ConditionScope.() -> Boolean): Condition = Condition { holds() }

/** Program code as a task (Dolphin `action { }`). */
public fun action(label: String = "action", block: suspend Program.() -> Unit): Task = Task.Action(label, block)

/** Wait for [condition]; follow with `then task` (Dolphin `waitFor c then t`). */
public fun waitFor(condition: ConditionScope.() -> Boolean): Waiting = Waiting(condition(condition))

/** A `waitFor` that still needs its `then`. */
public class Waiting internal constructor(private val condition: Condition) {
    /** Run [task] once the condition holds. */
    public infix fun then(task: Task): Task = Task.WaitFor(condition, task)
}

/** Every branch runs its task when its condition holds; done when all have (Dolphin `allOf { when c then t }`). */
public fun allOf(build: BranchesBuilder.() -> Unit): Task = Task.AllOf(BranchesBuilder().apply(build).branches())

/** Runs only the first branch whose condition holds (Dolphin `oneOf { when c then t }`). */
public fun oneOf(build: BranchesBuilder.() -> Unit): Task = Task.OneOf(BranchesBuilder().apply(build).branches())

/** Collects the `whenever { c } then t` branches of [allOf] and [oneOf]. */
@PodDsl
public class BranchesBuilder internal constructor() {
    private val list = mutableListOf<Branch>()

    /** A branch that fires when [condition] holds (Dolphin `when`); finish it with `then task`. */
    public fun whenever(condition: ConditionScope.() -> Boolean): BranchStart = BranchStart(condition(condition))

    /** A branch that fires at once (Dolphin `otherwise`). */
    public fun otherwise(task: Task) {
        list += Branch(Condition { true }, task)
    }

    /** The start of a branch: its condition. */
    public inner class BranchStart internal constructor(private val condition: Condition) {
        /** The task the branch runs. */
        public infix fun then(task: Task) {
            list += Branch(condition, task)
        }
    }

    internal fun branches(): List<Branch> {
        require(list.isNotEmpty()) { "allOf/oneOf: give at least one whenever { … } then … branch" }
        return list.toList()
    }
}

/** Run [task], handling its failure with what follows: `watch(t) onError ignore` (Dolphin `watch`). */
public fun watch(task: Task): Watching = Watching(task)

/** A `watch` that still needs its `onError`. */
public class Watching internal constructor(private val task: Task) {
    /** Handle a failure by [handler]: [ignore] or [propagate]. */
    public infix fun onError(handler: ErrorHandler): Task = Task.Watch(task, handler)

    /** Handle a failure by running the task [recover] returns for it. */
    public infix fun onError(recover: (Throwable) -> Task): Task = Task.Watch(task, ErrorHandler.Recover(recover))
}

/** Swallow the failure (Dolphin `ignore`). */
public val ignore: ErrorHandler get() = ErrorHandler.Ignore

/** Pass the failure on (Dolphin `propagate`). */
public val propagate: ErrorHandler get() = ErrorHandler.Propagate

private inline fun <reified T : Task> flatten(task: Task, children: (T) -> List<Task>): List<Task> =
    if (task is T) children(task) else listOf(task)
