package pod.mavlink.param

import pod.mavlink.command.CommandRoundTrip
import pod.mavlink.command.CommandTiming
import pod.mavlink.protocol.Outcome
import pod.mavlink.protocol.ProtocolMachine
import pod.mavlink.protocol.Step
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
) : ProtocolMachine<Parameter, Unit, Parameter> {

    private var startedAt = 0L
    private var lastSentAt = 0L
    private var attempts = 0
    private var attemptTimeout = 0L
    private var mismatches = 0
    private var wakeAt = Long.MAX_VALUE
    private var done = false

    override fun start(now: Long): Step<Unit, Parameter> {
        startedAt = now
        attemptTimeout = roundTrip.attemptTimeoutNanos
        return send(now)
    }

    override fun onMessage(message: Parameter, now: Long): Step<Unit, Parameter> {
        val value = message
        if (done || value.name != name) return Step.NOTHING
        if (attempts == 1) roundTrip.sample(now - lastSentAt)
        if (writing == null || sameValue(value)) return finish(Outcome.Done(value))
        if (++mismatches >= 2) return finish(Outcome.Failed(ParamRejected(name, writing, value.value)))
        return send(now)
    }

    override fun onTimer(now: Long): Step<Unit, Parameter> {
        if (done || now < wakeAt) return Step.NOTHING
        if (now - startedAt >= timing.timeout.inWholeNanoseconds) {
            return finish(Outcome.Failed(ParamTimeout(name, attempts, (now - startedAt).nanoseconds)))
        }
        attemptTimeout = (attemptTimeout * 3 / 2).coerceAtMost(timing.maxAttemptTimeout.inWholeNanoseconds)
        return send(now)
    }

    private fun sameValue(value: Parameter): Boolean {
        val wanted = writing ?: return true
        val kind = type ?: value.type
        return if (kind.isInteger) value.value.toLong() == wanted.toLong() else value.value.toFloat() == wanted.toFloat()
    }

    private fun send(now: Long): Step<Unit, Parameter> {
        attempts++
        lastSentAt = now
        wakeAt = minOf(now + attemptTimeout, startedAt + timing.timeout.inWholeNanoseconds)
        return Step(listOf(Unit), wakeAt)
    }

    private fun finish(outcome: Outcome<Parameter>): Step<Unit, Parameter> {
        done = true
        wakeAt = Long.MAX_VALUE
        return Step(wakeAt = Step.NEVER, outcome = outcome)
    }
}
