package pod.core.engine

import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.getAndUpdate
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.platform.Platform
import pod.core.platform.PlatformVehicle
import pod.core.platform.SafeState
import pod.core.vehicle.Position
import kotlin.time.Duration

/**
 * A running program: what its code can do. Loops and variables are plain Kotlin; tasks run with
 * [execute], vehicles come from [pick] and go back with [release]. Created by [Engine.run].
 */
public class Program internal constructor(
    /** The engine running this program. */
    public val engine: Engine,
    /** Numbers the programs of [engine] in the order they start, from 1 ([EngineEvent.ProgramEnded] names it). */
    public val id: Int,
) {
    private val _picked = MutableStateFlow<Set<Int>>(emptySet())
    private val runner = TaskRunner(engine, this)

    /** The fleet this program's engine runs on ([Engine.platform]). */
    public val platform: Platform get() = engine.platform

    /** Ids of the vehicles this program holds (picked and not yet released). */
    public val picked: StateFlow<Set<Int>> = _picked.asStateFlow()

    /** How long a vehicle may go unheard during a task before the task fails with VehicleLost (Dolphin `setConnectionTimeout`). */
    public var connectionTimeout: Duration = engine.config.connectionTimeout

    /** What a vehicle does when its task is cancelled, for tasks that do not say. */
    public var safeState: SafeState = engine.config.safeState

    /** Every vehicle the platform knows now. */
    public val vehicles: VehicleSet get() = VehicleSet(platform.vehicles.value)

    /** Runs [task] and returns when it is done; throws what it failed with. */
    public suspend fun execute(task: Task) {
        runner.run(task, vehicles = null, parent = currentCoroutineContext()[RunningTask]?.id ?: 0)
    }

    /**
     * Waits until [request.count][PickRequest.count] free vehicles meet [request] and takes them for
     * this program; throws [PickTimeout] naming the request when its timeout passes first.
     */
    public suspend fun pick(request: PickRequest): VehicleSet {
        // Noted outside the timeout block: the timeout may fire after take() succeeded and before the
        // block returns, and vehicles this program now holds must be returned, not reported as a timeout.
        var taken: VehicleSet? = null
        withTimeoutOrNull(engine.wall(request.timeout)) {
            while (taken == null) {
                val candidates = awaitValue(engine.revision) { candidates(request).takeIf { it.size >= request.count }?.take(request.count) }
                if (take(candidates.map { it.id })) taken = VehicleSet(candidates)
            }
        }
        val picked = taken ?: throw PickTimeout(request, candidates(request).size, request.timeout)
        engine.emit(EngineEvent.Picked(engine.now(), picked.ids.toList()))
        return picked
    }

    /** Gives [vehicles] back; they must have been picked by this program. */
    public fun release(vehicles: Iterable<PlatformVehicle>) {
        val ids = vehicles.mapTo(LinkedHashSet()) { it.id }
        // Checked and removed in one step: two concurrent releases of one vehicle must not both pass
        // the check, or the second would drop another program's pick of it from pickedByAny.
        var missing = emptySet<Int>()
        _picked.update { held ->
            missing = ids - held
            if (missing.isEmpty()) held - ids else held
        }
        if (missing.isNotEmpty()) throw NotPicked(missing)
        engine.pickedByAny.update { it - ids }
        engine.emit(EngineEvent.Released(engine.now(), ids.toList()))
    }

    /** Gives [vehicle] back. */
    public fun release(vehicle: PlatformVehicle): Unit = release(listOf(vehicle))

    /**
     * A new, empty mission queue that counts durations in this program's vehicle time (the
     * engine's clock and the platform's time scale). Fly it with a [Task.FlyQueue] (pod-dsl:
     * `queue on vehicle`) and feed it from any task.
     */
    public fun missionQueue(): pod.core.queue.MissionQueue = pod.core.queue.MissionQueue(engine.config.timebase, engine.platform.timeScale)

    /** Publishes [text] as a [EngineEvent.Message] (Dolphin `message`). */
    public fun message(text: String) {
        engine.emit(EngineEvent.Message(engine.now(), text))
    }

    /**
     * Remaining battery of [vehicle], 0..1, or NaN while it reports none: unknown is neither full
     * nor empty, every comparison with it is false (see [ConditionScope.battery]).
     */
    public fun battery(vehicle: PlatformVehicle): Double = vehicle.battery.value?.remaining ?: Double.NaN

    /** True once [vehicle] reports its remaining charge. */
    public fun batteryKnown(vehicle: PlatformVehicle): Boolean = vehicle.battery.value?.remaining != null

    /** Where [vehicle] is, or null before its first report. */
    public fun position(vehicle: PlatformVehicle): Position? = vehicle.position.value

    /** Suspends until [condition] holds (evaluated again only when what it reads changes). */
    public suspend fun await(condition: Condition) {
        awaitCondition(engine.revision, condition, engine.loitering)
    }

    internal fun releaseAll() {
        val held = _picked.getAndUpdate { emptySet() }
        if (held.isEmpty()) return
        engine.pickedByAny.update { it - held }
        engine.emit(EngineEvent.Released(engine.now(), held.toList()))
    }

    private fun ConditionScope.candidates(request: PickRequest): List<PlatformVehicle> {
        val taken = read(engine.pickedByAny)
        val busy = read(engine.busy)
        return read(platform.vehicles).filter { it.id !in taken && it.id !in busy && request.accepts(it, this) }
    }

    private fun candidates(request: PickRequest): List<PlatformVehicle> = TrackingScope().candidates(request)

    private fun take(ids: List<Int>): Boolean {
        var ok = false
        engine.pickedByAny.update { held ->
            ok = ids.none { it in held } && ids.none { it in engine.busy.value }
            if (ok) held + ids else held
        }
        if (ok) _picked.update { it + ids }
        return ok
    }
}
