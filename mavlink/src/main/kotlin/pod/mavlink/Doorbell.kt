package pod.mavlink

import kotlinx.coroutines.CancellableContinuation
import kotlinx.coroutines.suspendCancellableCoroutine
import java.util.concurrent.atomic.AtomicReference
import kotlin.coroutines.resume
import kotlin.coroutines.resumeWithException

/**
 * How the receive path tells an exchange's driving coroutine to look again (see [run]): [ring]
 * from any thread; the coroutine [take]s a ring without suspending or [await]s one; [close]
 * makes every later wait throw. Rings do not count: several before a wait are one.
 *
 * It does what a conflated `Channel<Unit>` did here, for a fraction of its cost: one atomic
 * reference instead of a channel's segments, which every command allocated, and a [take] that is
 * one volatile read while the caller polls ([HotWait]).
 */
internal class Doorbell {
    private val state = AtomicReference<Any>(IDLE)

    /** Wakes the waiter, or leaves a ring for the next [take] or [await]. */
    fun ring() {
        while (true) {
            when (val s = state.get()) {
                IDLE -> if (state.compareAndSet(IDLE, RUNG)) return
                is CancellableContinuation<*> -> if (state.compareAndSet(s, IDLE)) {
                    // A waiter cancelled meanwhile ignores this; its driver looks again anyway.
                    @Suppress("UNCHECKED_CAST")
                    (s as CancellableContinuation<Unit>).resume(Unit)
                    return
                }
                else -> return // rung already, or closed
            }
        }
    }

    /** Every wait from now on throws [error]; a waiter now is woken with it. */
    fun close(error: Throwable) {
        while (true) {
            val s = state.get()
            if (s is Closed) return
            if (state.compareAndSet(s, Closed(error))) {
                if (s is CancellableContinuation<*>) s.resumeWithException(error)
                return
            }
        }
    }

    /** Takes a ring if there is one, without waiting; throws the [close] error once closed. */
    fun take(): Boolean {
        val s = state.get()
        if (s is Closed) throw s.error
        return s === RUNG && state.compareAndSet(RUNG, IDLE)
    }

    /** Suspends until the next ring (at once if one is waiting); throws the [close] error once closed. */
    suspend fun await() {
        if (take()) return
        suspendCancellableCoroutine { waiter ->
            waiter.invokeOnCancellation { state.compareAndSet(waiter, IDLE) }
            while (true) {
                when (val s = state.get()) {
                    RUNG -> if (state.compareAndSet(RUNG, IDLE)) {
                        waiter.resume(Unit)
                        return@suspendCancellableCoroutine
                    }
                    IDLE -> if (state.compareAndSet(IDLE, waiter)) return@suspendCancellableCoroutine
                    is Closed -> {
                        waiter.resumeWithException(s.error)
                        return@suspendCancellableCoroutine
                    }
                    else -> error("one waiter at a time")
                }
            }
        }
    }

    private class Closed(val error: Throwable)

    private companion object {
        val IDLE = Any()
        val RUNG = Any()
    }
}
