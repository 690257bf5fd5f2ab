package pod.mavlink

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.selects.onTimeout
import kotlinx.coroutines.selects.select
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import pod.core.vehicle.StatusText
import pod.core.vehicle.VehicleLost
import pod.mavlink.protocol.Outcome
import pod.mavlink.protocol.ProtocolMachine
import pod.mavlink.protocol.Step
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.Duration.Companion.seconds

/**
 * How a protocol talks to a vehicle over MAVLink: what the exchange is called ([during], in
 * [VehicleLost] and [MavlinkVehicle.awaiting]), which of the vehicle's messages it reads ([pick]:
 * decoded and filtered, null to skip), how its messages go out ([encode]), and:
 * - [giveUpAfter]: the silence after which it fails, shown in [Awaiting];
 * - [isAnswer]: whether a picked message answers the exchange (the awaiting notice clears), or only
 *   tells that the vehicle is alive;
 * - [texts]: which of the vehicle's joined status-text lines it also reads (null: none);
 * - [onCancel]: what to tell the vehicle when the caller cancels the exchange.
 */
internal class Wire<I, O>(
    val during: String,
    val pick: (InboundMessage) -> I?,
    val encode: (O) -> Any,
    val giveUpAfter: Duration? = null,
    val isAnswer: (I) -> Boolean = { true },
    val texts: ((StatusText) -> I?)? = null,
    val onCancel: List<O> = emptyList(),
)

/**
 * Runs [machine] against this vehicle until it ends, and returns its result or throws its error:
 * sends what each step says, waits for the vehicle's messages ([Wire.pick]) with the machine's
 * timer, feeds what arrives, in order and without loss. Listening starts before the machine's
 * first message goes out, so a quick reply cannot slip past. Fails with [VehicleLost] as soon as
 * the vehicle is marked lost. Time is the station's clock ([MavlinkVehicle.clock]) and waits are
 * the coroutine dispatcher's, so the whole exchange runs in virtual time under a test scheduler.
 *
 * [afterStep] is called after each step has been carried out (for progress). Cancelled, the
 * driver sends [Wire.onCancel] within [CANCEL_SEND_LIMIT] before it rethrows.
 */
internal suspend fun <I, O, T> MavlinkVehicle.run(
    machine: ProtocolMachine<I, O, T>,
    wire: Wire<I, O>,
    afterStep: () -> Unit = {},
): T {
    // No coroutine of its own: replies, texts and the loss reach the inbox from the receive path
    // and the station's tracking loop, so the caller is resumed once per input and the exchange
    // ends without waiting for children to finish.
    val origin = clock.markNow()
    fun now() = origin.elapsedNow().inWholeNanoseconds
    val inbox = Channel<I>(Channel.UNLIMITED)
    val watch = ExchangeWatch(this, wire.during, wire.giveUpAfter)
    val untap = tap { inbound ->
        wire.pick(inbound)?.let {
            if (wire.isAnswer(it)) watch.answered()
            inbox.trySend(it)
        }
    }
    val untapTexts = wire.texts?.let { read -> tapTexts { line -> read(line)?.let { inbox.trySend(it) } } }
    val unwatchLoss = onLost { inbox.close(VehicleLost(systemId, wire.during)) }
    try {
        var wakeAt = Step.NEVER
        var step = machine.start(now())
        while (true) {
            for (message in step.send) send(wire.encode(message))
            if (step.send.isNotEmpty()) watch.sent()
            if (step.wakeAt != Step.KEEP) wakeAt = step.wakeAt
            afterStep()
            when (val outcome = step.outcome) {
                null -> Unit
                is Outcome.Done -> return outcome.value
                is Outcome.Failed -> throw outcome.error
            }
            // A message already waiting is handled without arming a timer (bursts: a download's
            // window, an upload's requests); a select prefers it over an expired timer all the same.
            val waiting = inbox.tryReceive()
            waiting.exceptionOrNull()?.let { throw it } // closed: the vehicle was lost
            val timer = wakeAt
            step = if (waiting.isSuccess) {
                machine.onMessage(waiting.getOrThrow(), now())
            } else {
                select {
                    inbox.onReceive { machine.onMessage(it, now()) }
                    if (timer != Step.NEVER) onTimeout((timer - now()).coerceAtLeast(0).nanoseconds) { machine.onTimer(now()) }
                }
            }
        }
        @Suppress("UNREACHABLE_CODE")
        error("unreachable")
    } catch (e: CancellationException) {
        if (wire.onCancel.isNotEmpty()) {
            // Bounded, so a stuck link cannot hold up the cancel.
            withContext(NonCancellable) {
                withTimeoutOrNull(CANCEL_SEND_LIMIT) { for (message in wire.onCancel) send(wire.encode(message)) }
            }
        }
        throw e
    } finally {
        untap()
        untapTexts?.invoke()
        unwatchLoss()
        watch.ended()
    }
}

/** Longest wait to hand [Wire.onCancel] to the link. */
private val CANCEL_SEND_LIMIT = 500.milliseconds

/**
 * Tracks one exchange's silence for [MavlinkVehicle.awaiting]: requests sent since the vehicle
 * last answered, and since when. Updated on each send, so it needs no timer of its own: a driver
 * that resends on its attempt timeout refreshes it as it goes.
 */
internal class ExchangeWatch(private val vehicle: MavlinkVehicle, private val what: String, private val giveUpAfter: Duration?) {
    @Volatile private var since = vehicle.clock.markNow()
    @Volatile private var sends = 0
    @Volatile private var shown: Awaiting? = null

    /** A request went to the vehicle. */
    fun sent() {
        sends++
        val waited = since.elapsedNow()
        if (waited >= QUIET) {
            val awaiting = Awaiting(vehicle.systemId, what, sends, waited, giveUpAfter)
            shown = awaiting
            vehicle._awaiting.value = awaiting
        }
    }

    /** The vehicle answered this exchange. */
    fun answered() {
        since = vehicle.clock.markNow()
        sends = 0
        clear()
    }

    /** The exchange is over. */
    fun ended() = clear()

    private fun clear() {
        val mine = shown ?: return
        shown = null
        vehicle._awaiting.compareAndSet(mine, null)
    }

    companion object {
        /** Silence before the wait is shown: longer than a normal round trip and its first resend. */
        val QUIET: Duration = 2.seconds
    }
}
