package pod.mavlink.protocol

import pod.core.PodException

/**
 * One side of a MAVLink protocol exchange (a mission transfer, a command, a parameter read) as a
 * pure state machine: no coroutine, no clock, no socket. The driver ([run]) feeds it what the
 * vehicle sends and the expiry of the timer it asked for, each with the driver's clock reading in
 * nanoseconds, and does what each [Step] says.
 *
 * [I] is what it reads (already decoded and filtered), [O] what it sends, [T] its result.
 */
internal interface ProtocolMachine<in I, out O, out T> {
    /** The exchange begins at [now]: usually the first request and a timer. */
    fun start(now: Long): Step<O, T>

    /** [message] arrived at [now]. */
    fun onMessage(message: I, now: Long): Step<O, T>

    /** The timer set by an earlier step expired; [now] is at or after its wake time. */
    fun onTimer(now: Long): Step<O, T>
}

/**
 * What a [ProtocolMachine] wants after an event: [send] these messages, in order; wake it at
 * [wakeAt] (the driver's clock, nanoseconds; [KEEP] leaves the timer as it was, [NEVER] stops it);
 * and, once it is over, its [outcome].
 */
internal class Step<out O, out T>(
    val send: List<O> = emptyList(),
    val wakeAt: Long = KEEP,
    val outcome: Outcome<T>? = null,
) {
    override fun toString(): String = "Step(send=$send, wakeAt=$wakeAt, outcome=$outcome)"

    companion object {
        /** Leave the timer as it is. */
        const val KEEP = -1L

        /** No timer. */
        const val NEVER = Long.MAX_VALUE

        /** Nothing to do, timer unchanged. */
        val NOTHING = Step<Nothing, Nothing>()

        /** The exchange ended with [value]. */
        fun <O, T> done(value: T, send: List<O> = emptyList()): Step<O, T> = Step(send, NEVER, Outcome.Done(value))

        /** The exchange ended with [error]. */
        fun failed(error: PodException): Step<Nothing, Nothing> = Step(wakeAt = NEVER, outcome = Outcome.Failed(error))
    }
}

/** How an exchange ended: with a result, or with the typed error its caller sees. */
internal sealed interface Outcome<out T> {
    data class Done<out T>(val value: T) : Outcome<T>

    data class Failed(val error: PodException) : Outcome<Nothing>
}
