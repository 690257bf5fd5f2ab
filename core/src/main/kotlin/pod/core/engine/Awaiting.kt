package pod.core.engine

import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.filter
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.merge
import pod.core.platform.PlatformVehicle

/**
 * A [ConditionScope] that remembers every flow it read and the value it saw; [loitering] is the
 * engine's set of vehicles established on a mission's final unlimited loiter.
 */
internal class TrackingScope(private val loitering: StateFlow<Set<Int>>? = null) : ConditionScope {
    val seen = LinkedHashMap<StateFlow<*>, Any?>()

    override fun <T> read(flow: StateFlow<T>): T {
        val value = flow.value
        if (flow !in seen) seen[flow] = value
        return value
    }

    override fun loitering(vehicle: PlatformVehicle): Boolean = loitering?.let { vehicle.id in read(it) } ?: false
}

/**
 * Evaluates [compute] until it returns a value, sleeping in between until one of the flows it read
 * changes (or, when it read none, until [fallback] changes). The first evaluation happens at once.
 */
internal suspend fun <T : Any> awaitValue(fallback: StateFlow<*>, loitering: StateFlow<Set<Int>>? = null, compute: ConditionScope.() -> T?): T {
    while (true) {
        val scope = TrackingScope(loitering)
        scope.compute()?.let { return it }
        if (scope.seen.isEmpty()) scope.read(fallback)
        val changes = scope.seen.map { (flow, value) -> flow.filter { it != value } }
        // merge() runs a channel and a coroutine per flow; most waits (a vehicle's link, one battery) read one flow.
        (changes.singleOrNull() ?: merge(*changes.toTypedArray())).first()
    }
}

/** Suspends until [condition] holds. */
internal suspend fun awaitCondition(fallback: StateFlow<*>, condition: Condition, loitering: StateFlow<Set<Int>>? = null) {
    awaitValue(fallback, loitering) { if (with(condition) { holds() }) Unit else null }
}
