package pod.mavlink.telemetry

import kotlinx.coroutines.ExperimentalForInheritanceCoroutinesApi
import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.flow.FlowCollector
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.onSubscription

/**
 * A [StateFlow] whose immutable value is built from primitive state only when someone reads it:
 * the receive path writes numbers (no object per frame), a reader gets the value object, built
 * once per change and cached, so two reads with no change between them return the same instance.
 *
 * Why not a MutableStateFlow: its value must be an object, so a position that changes with every
 * GLOBAL_POSITION_INT (10 Hz per vehicle) costs a new Position per frame, read or not. Here a frame
 * costs a lock and a few stores; the object is paid by the reader, at the reader's pace.
 *
 * It keeps StateFlow's meaning: [value] is the latest state; a collector gets the value at once,
 * then each later value that differs (equals) from the last it got, conflated when it is slow,
 * and never misses the last change (each change leaves a wake-up in a one-slot, drop-oldest
 * buffer, with no buffer and no work when nobody collects).
 *
 * A subclass keeps its state in fields guarded by [lock]: a writer changes them inside
 * `synchronized(lock)`, calls [changedLocked] there when they changed, and [wake] after leaving it.
 */
@OptIn(ExperimentalForInheritanceCoroutinesApi::class)
internal abstract class SnapshotStateFlow<T> : StateFlow<T> {
    /** Guards the subclass's state and the cached value. */
    protected val lock: Any = Any()
    private var version = 0L
    private var builtVersion = -1L
    private var built: T? = null
    private val changes = MutableSharedFlow<Unit>(extraBufferCapacity = 1, onBufferOverflow = BufferOverflow.DROP_OLDEST)

    /** The value of the current state; called under [lock]. */
    protected abstract fun snapshot(): T

    /** The state changed (call under [lock]): the next read builds a new value. */
    protected fun changedLocked() {
        version++
    }

    /** Wakes collectors after a change (call outside [lock]); nothing to do, and nothing allocated, when none collects. */
    protected fun wake() {
        changes.tryEmit(Unit)
    }

    @Suppress("UNCHECKED_CAST")
    override val value: T
        get() = synchronized(lock) {
            if (builtVersion != version) {
                built = snapshot()
                builtVersion = version
            }
            built as T
        }

    override val replayCache: List<T> get() = listOf(value)

    override suspend fun collect(collector: FlowCollector<T>): Nothing {
        var last: Any? = NOTHING
        // Subscribed before the first read: a change after it leaves a wake-up, so none is missed.
        changes.onSubscription { emit(Unit) }.collect {
            val current = value
            if (current != last) {
                last = current
                collector.emit(current)
            }
        }
    }

    override fun toString(): String = "SnapshotStateFlow($value)"

    private companion object {
        /** No value emitted yet (null is a value). */
        val NOTHING = Any()
    }
}
