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
 *
 * Public because the vehicle side speaks the same contract: a
 * [pod.mavlink.vehicle.VehicleMachine] (a simulator's mission server) answers with steps too, and
 * the simulator that wraps one passes them on.
 */
public class Step<out O, out T>(
    /** The messages to send, in order. */
    public val send: List<O> = emptyList(),
    /** When to wake the machine next: a clock reading in nanoseconds, [KEEP] or [NEVER]. */
    public val wakeAt: Long = KEEP,
    /** How the exchange ended, or null while it goes on (always null on the vehicle side). */
    public val outcome: Outcome<T>? = null,
) {
    override fun toString(): String = "Step(send=$send, wakeAt=$wakeAt, outcome=$outcome)"

    /** The timer values and the steps every machine uses. */
    public companion object {
        /** Leave the timer as it is. */
        public const val KEEP: Long = -1L

        /** No timer. */
        public const val NEVER: Long = Long.MAX_VALUE

        /** Nothing to do, timer unchanged. */
        public val NOTHING: Step<Nothing, Nothing> = Step()

        /** The exchange ended with [value]. */
        internal fun <O, T> done(value: T, send: List<O> = emptyList()): Step<O, T> = Step(send, NEVER, Outcome.Done(value))

        /** The exchange ended with [error]. */
        internal fun failed(error: PodException): Step<Nothing, Nothing> = Step(wakeAt = NEVER, outcome = Outcome.Failed(error))
    }
}

/** How an exchange ended: with a result, or with the typed error its caller sees. */
public sealed interface Outcome<out T> {
    /** It ended with [value]. */
    public data class Done<out T>(
        /** The exchange's result. */
        public val value: T,
    ) : Outcome<T>

    /** It ended with [error]. */
    public data class Failed(
        /** What the caller is thrown. */
        public val error: PodException,
    ) : Outcome<Nothing>
}
