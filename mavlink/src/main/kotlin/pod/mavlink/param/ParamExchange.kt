package pod.mavlink.param

import pod.mavlink.command.CommandRoundTrip
import pod.mavlink.command.CommandTiming
import kotlin.time.Duration.Companion.nanoseconds

/**
 * Reading one parameter (PARAM_REQUEST_READ) or writing it (PARAM_SET), each answered by
 * PARAM_VALUE, as a pure state machine: the request is repeated on the attempt timeout until a
 * PARAM_VALUE with the name arrives or the link stays silent for the timeout. A write is confirmed
 * when the reported value is the one written; a first report of another value may be a stale
 * broadcast, so the write is sent again, and a second one means the vehicle refused.
 */
internal class ParamExchange(
    private val name: String,
    /** The value to write, or null to read. */
    private val writing: Double?,
    private val type: ParamType?,
    private val timing: CommandTiming,
    private val roundTrip: CommandRoundTrip,
) {
    /** [send] = send the request now; [wakeAt] absolute; [result] or [error] at the end. */
    data class Step(val send: Boolean = false, val wakeAt: Long = Long.MAX_VALUE, val result: Parameter? = null, val error: ParamException? = null)

    private var startedAt = 0L
    private var lastSentAt = 0L
    private var attempts = 0
    private var attemptTimeout = 0L
    private var mismatches = 0
    private var wakeAt = Long.MAX_VALUE
    private var done = false

    fun start(now: Long): Step {
        startedAt = now
        attemptTimeout = roundTrip.attemptTimeoutNanos
        return send(now)
    }

    fun onValue(value: Parameter, now: Long): Step {
        if (done || value.name != name) return Step(wakeAt = wakeAt)
        if (attempts == 1) roundTrip.sample(now - lastSentAt)
        if (writing == null || sameValue(value)) return finish(Step(result = value))
        if (++mismatches >= 2) return finish(Step(error = ParamRejected(name, writing, value.value)))
        return send(now)
    }

    fun onTimer(now: Long): Step {
        if (done || now < wakeAt) return Step(wakeAt = wakeAt)
        if (now - startedAt >= timing.timeout.inWholeNanoseconds) {
            return finish(Step(error = ParamTimeout(name, attempts, (now - startedAt).nanoseconds)))
        }
        attemptTimeout = (attemptTimeout * 3 / 2).coerceAtMost(timing.maxAttemptTimeout.inWholeNanoseconds)
        return send(now)
    }

    private fun sameValue(value: Parameter): Boolean {
        val wanted = writing ?: return true
        val kind = type ?: value.type
        return if (kind.isInteger) value.value.toLong() == wanted.toLong() else value.value.toFloat() == wanted.toFloat()
    }

    private fun send(now: Long): Step {
        attempts++
        lastSentAt = now
        wakeAt = minOf(now + attemptTimeout, startedAt + timing.timeout.inWholeNanoseconds)
        return Step(send = true, wakeAt = wakeAt)
    }

    private fun finish(step: Step): Step {
        done = true
        wakeAt = Long.MAX_VALUE
        return step
    }
}
