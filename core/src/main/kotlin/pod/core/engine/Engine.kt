package pod.core.engine

import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asSharedFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.withContext
import pod.core.platform.Platform
import kotlin.time.Duration

/**
 * Runs Dolphin programs against a [Platform]. One engine per fleet: it knows which vehicle is in
 * which running task (a vehicle is in at most one) and publishes what happens as [events].
 *
 * ```
 * Engine(platform).run {
 *     val v = pick(PickRequest(count = 1))
 *     execute(Task.Bound(Task.Fly(survey), v))
 * }
 * ```
 * pod-dsl gives the same program its Dolphin shape.
 */
public class Engine(
    /** The fleet programs fly: its vehicles, and how a mission is flown and a vehicle made safe. */
    public val platform: Platform,
    /** How programs run. */
    public val config: EngineConfig = EngineConfig(),
) {
    private val started = config.timebase.clock.markNow()
    private val _events = MutableSharedFlow<EngineEvent>(extraBufferCapacity = Int.MAX_VALUE)
    private val _busy = MutableStateFlow(IntTrieMap.empty<String>())
    private val _revision = MutableStateFlow(0L)
    private val taskIds = MutableStateFlow(0)
    private val programIds = MutableStateFlow(0)

    /** Everything that happens, in order. Subscribe before [run] to see a program from its start. */
    public val events: SharedFlow<EngineEvent> = _events.asSharedFlow()

    /** Vehicle id → label of the running task that holds it. */
    public val busy: StateFlow<Map<Int, String>> = _busy.asStateFlow()

    /** Ids of the vehicles some program on this engine holds. */
    internal val pickedByAny = MutableStateFlow<Set<Int>>(emptySet())

    /** Ids of the vehicles established on the unlimited loiter that ends the mission they fly (`loitering(v)`). */
    internal val loitering = MutableStateFlow<Set<Int>>(emptySet())

    /** Bumped with every event; conditions that read no telemetry are evaluated again when it changes. */
    internal val revision: StateFlow<Long> = _revision.asStateFlow()

    /**
     * Runs [block] as a program and returns its result. When its code is done, however it ends, the
     * engine publishes [EngineEvent.ProgramEnded] (so a consumer of [events] knows when to stop);
     * the vehicles it still holds are released next. Cancelling the caller cancels its tasks, and
     * every vehicle they flew is made safe before this returns.
     */
    public suspend fun <T> run(block: suspend Program.() -> T): T {
        val program = Program(this, nextId(programIds))
        try {
            return coroutineScope {
                try {
                    program.block()
                } finally {
                    emit(EngineEvent.ProgramEnded(now(), program.id))
                }
            }
        } finally {
            withContext(NonCancellable) { program.releaseAll() }
        }
    }

    /** Vehicle time since the engine was made. */
    internal fun now(): Duration = started.elapsedNow() * platform.timeScale

    /** A vehicle-time span as wall time. */
    internal fun wall(vehicleTime: Duration): Duration = vehicleTime / platform.timeScale

    internal fun nextTaskId(): Int = nextId(taskIds)

    private fun nextId(counter: MutableStateFlow<Int>): Int {
        var id = 0
        counter.update { id = it + 1; id }
        return id
    }

    internal fun emit(event: EngineEvent) {
        _events.tryEmit(event)
        _revision.update { it + 1 }
    }

    /** Marks [vehicleId] as held by [task], or throws [VehicleBusy]. */
    internal fun claim(vehicleId: Int, task: String) {
        var holder: String? = null
        _busy.update { held ->
            holder = held[vehicleId]
            if (holder != null) held else held.put(vehicleId, task)
        }
        holder?.let { throw VehicleBusy(vehicleId, task, it) }
    }

    internal fun unclaim(vehicleId: Int) {
        _busy.update { it.remove(vehicleId) }
        _revision.update { it + 1 }
    }
}
