package pod.core.engine

import kotlinx.coroutines.flow.update
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.selects.select
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.platform.PlatformVehicle
import pod.core.platform.queueCapable
import pod.core.platform.surveyCapable
import pod.core.platform.SafeState
import pod.core.queue.QueueNeedsOneVehicle
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.VehicleLost
import kotlin.coroutines.AbstractCoroutineContextElement
import kotlin.coroutines.CoroutineContext

/** The task whose code is running: tasks a [Task.Action] executes become its children. */
internal class RunningTask(val id: Int) : AbstractCoroutineContextElement(Key) {
    companion object Key : CoroutineContext.Key<RunningTask>
}

/**
 * Runs task trees for one [Program]. Every task runs in the coroutine of the task that started it
 * (children in child coroutines), so cancellation flows down the tree; a [Task.Fly] that is
 * cancelled or fails makes its vehicle safe before it returns.
 */
internal class TaskRunner(private val engine: Engine, private val program: Program) {
    suspend fun run(task: Task, vehicles: VehicleSet?, parent: Int) {
        val id = engine.nextTaskId()
        val label = task.label
        val on = if (task is Task.Bound) task.vehicles else vehicles
        engine.emit(EngineEvent.TaskStarted(engine.now(), id, parent, label, on?.ids?.toList().orEmpty()))
        try {
            body(task, vehicles, id)
        } catch (e: CancellationException) {
            engine.emit(EngineEvent.TaskCancelled(engine.now(), id, label))
            throw e
        } catch (e: Throwable) {
            engine.emit(EngineEvent.TaskFailed(engine.now(), id, label, e))
            throw e
        }
        engine.emit(EngineEvent.TaskCompleted(engine.now(), id, label))
    }

    private suspend fun body(task: Task, vehicles: VehicleSet?, id: Int) {
        when (task) {
            is Task.Fly -> fly(task, vehicles ?: throw UnboundTask(task.label), id)
            is Task.FlyQueue -> flyQueue(task, vehicles ?: throw UnboundTask(task.label), id)
            is Task.Survey -> survey(task, vehicles ?: throw UnboundTask(task.label))
            is Task.Sequence -> task.tasks.forEach { run(it, vehicles, id) }
            is Task.Concurrent -> coroutineScope { task.tasks.forEach { launch { run(it, vehicles, id) } } }
            is Task.Until -> until(task, vehicles, id)
            is Task.WaitFor -> {
                awaitCondition(engine.revision, task.condition, engine.loitering)
                run(task.task, vehicles, id)
            }
            is Task.AllOf -> coroutineScope {
                task.branches.forEach { branch ->
                    launch {
                        awaitCondition(engine.revision, branch.condition, engine.loitering)
                        run(branch.task, vehicles, id)
                    }
                }
            }
            is Task.OneOf -> {
                val chosen = awaitValue(engine.revision, engine.loitering) { task.branches.firstOrNull { with(it.condition) { holds() } } }
                run(chosen.task, vehicles, id)
            }
            is Task.During -> withTimeoutOrNull(engine.wall(task.limit)) { run(task.task, vehicles, id) }
            is Task.Idle -> delay(engine.wall(task.time))
            is Task.Watch -> watch(task, vehicles, id)
            is Task.Action -> withContext(RunningTask(id)) { task.block(program) }
            is Task.Bound -> run(task.task, task.vehicles, id)
        }
    }

    private suspend fun until(task: Task.Until, vehicles: VehicleSet?, id: Int) = coroutineScope {
        val body = async { run(task.task, vehicles, id) }
        val stop = async { awaitCondition(engine.revision, task.condition, engine.loitering) }
        select {
            body.onAwait { stop.cancel() }
            stop.onAwait { body.cancel() }
        }
    }

    private suspend fun watch(task: Task.Watch, vehicles: VehicleSet?, id: Int) {
        try {
            run(task.task, vehicles, id)
        } catch (e: CancellationException) {
            throw e
        } catch (e: Throwable) {
            when (val handler = task.onError) {
                ErrorHandler.Ignore -> Unit
                ErrorHandler.Propagate -> throw e
                is ErrorHandler.Recover -> run(handler.recover(e), vehicles, id)
            }
        }
    }

    private suspend fun fly(task: Task.Fly, vehicles: VehicleSet, id: Int) {
        if (vehicles.isEmpty()) throw UnboundTask(task.label)
        coroutineScope { vehicles.forEach { vehicle -> launch { flyOne(task, vehicle, id) } } }
    }

    private suspend fun flyOne(task: Task.Fly, vehicle: PlatformVehicle, id: Int) {
        engine.emit(EngineEvent.Flying(engine.now(), id, vehicle.id, task.mission))
        steer(task.label, vehicle, task.onCancel) {
            try {
                engine.platform.fly(vehicle, task.mission).collect {
                    if (it is pod.core.platform.MissionEvent.Loitering) engine.loitering.update { held -> held + vehicle.id }
                    engine.emit(EngineEvent.Mission(engine.now(), id, vehicle.id, it))
                }
            } finally {
                engine.loitering.update { held -> held - vehicle.id }
            }
        }
    }

    private suspend fun flyQueue(task: Task.FlyQueue, vehicles: VehicleSet, id: Int) {
        val vehicle = vehicles.singleOrNull() ?: throw if (vehicles.isEmpty()) UnboundTask(task.label) else QueueNeedsOneVehicle(vehicles.size)
        steer(task.label, vehicle, task.onCancel) {
            coroutineScope {
                // The queue's own events, as the program's: `pod run` shows elements start and end.
                val relay = launch(start = kotlinx.coroutines.CoroutineStart.UNDISPATCHED) { task.queue.events.collect { engine.emit(EngineEvent.Queue(engine.now(), id, vehicle.id, it)) } }
                engine.platform.queueCapable().flyQueue(vehicle, task.queue, task.whenEmpty)
                relay.cancel()
            }
        }
    }

    private suspend fun survey(task: Task.Survey, vehicles: VehicleSet) {
        val vehicle = vehicles.singleOrNull() ?: throw if (vehicles.isEmpty()) UnboundTask(task.label) else pod.core.workflow.SurveyNeedsOneVehicle(vehicles.size)
        steer(task.label, vehicle, task.onCancel) { engine.platform.surveyCapable().flySurvey(vehicle, task.job) }
    }

    /**
     * Runs [flight] with [vehicle] claimed for [label]: fails with [VehicleLost] once the vehicle is
     * unheard for the connection timeout, and makes it safe ([onCancel] or the program's choice)
     * when the flight fails or is cancelled, unless the vehicle's autopilot or pilot ended it by
     * taking control ([pod.core.platform.AutopilotTookControl]).
     */
    private suspend fun steer(label: String, vehicle: PlatformVehicle, onCancel: SafeState?, flight: suspend () -> Unit) {
        engine.claim(vehicle.id, label)
        val safe = onCancel ?: program.safeState
        try {
            coroutineScope {
                val watchdog = launch { awaitLost(vehicle, label) }
                flight()
                watchdog.cancel()
            }
        } catch (e: VehicleLost) {
            throw e
        } catch (e: Throwable) {
            if (e !is pod.core.platform.AutopilotTookControl) makeSafe(vehicle, safe)
            throw e
        } finally {
            engine.unclaim(vehicle.id)
        }
    }

    /** Throws [VehicleLost] once [vehicle] has been unheard for the program's connection timeout. */
    private suspend fun awaitLost(vehicle: PlatformVehicle, label: String) {
        while (true) {
            awaitValue(engine.revision) { if (read(vehicle.connection) == ConnectionState.LOST) Unit else null }
            val back = withTimeoutOrNull(engine.wall(program.connectionTimeout)) {
                awaitValue(engine.revision) { if (read(vehicle.connection) == ConnectionState.CONNECTED) Unit else null }
            }
            if (back == null) throw VehicleLost(vehicle.id, "mission '$label'")
        }
    }

    private suspend fun makeSafe(vehicle: PlatformVehicle, state: SafeState) = withContext(NonCancellable) {
        val confirmed = if (vehicle.connection.value == ConnectionState.LOST) {
            false
        } else {
            try {
                withTimeoutOrNull(engine.config.safeTimeout) { engine.platform.makeSafe(vehicle, state) } != null
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                false
            }
        }
        engine.emit(EngineEvent.MadeSafe(engine.now(), vehicle.id, state, confirmed))
    }
}
