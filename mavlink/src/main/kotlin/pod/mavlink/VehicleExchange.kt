package pod.mavlink

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.NonCancellable
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
 * - [onCancel]: what to tell the vehicle when the caller cancels the exchange;
 * - [hotWaitNanos]: how long the caller polls for the next event before it suspends ([HotWait]),
 *   read before each wait: about the round trip the exchange expects on a quick link, 0 for none.
 */
internal class Wire<I, O>(
    val during: String,
    val pick: (InboundMessage) -> I?,
    val encode: (O) -> Any,
    val giveUpAfter: Duration? = null,
    val isAnswer: (I) -> Boolean = { true },
    val texts: ((StatusText) -> I?)? = null,
    val onCancel: List<O> = emptyList(),
    val hotWaitNanos: () -> Long = { 0L },
)

/**
 * Runs [machine] against this vehicle until it ends, and returns its result or throws its error:
 * sends what each step says, feeds it the vehicle's messages ([Wire.pick]) in order and without
 * loss, and its timer's expiries. Listening starts before the machine's first message goes out, so
 * a quick reply cannot slip past. Fails with [VehicleLost] as soon as the vehicle is marked lost.
 * Time is the station's clock ([MavlinkVehicle.clock]) and waits are the coroutine dispatcher's,
 * so the whole exchange runs in virtual time under a test scheduler.
 *
 * The machine is driven in place: a reply is fed to it on the receive path that delivered it, and
 * what it answers goes out from there when the link [sends in place][pod.mavlink.link.MavlinkLink.sendsInPlace]
 * (UDP, memory), so an upload's next item or a download's next request costs no thread hand-off.
 * The calling coroutine sends the first step, runs the timer, sends what could not go out in place
 * (TCP) and returns the outcome; a lock keeps the machine to one caller at a time.
 *
 * [afterStep] is called after each step has been carried out (for progress), on either thread; it
 * must not block. Cancelled, the driver sends [Wire.onCancel] within [CANCEL_SEND_LIMIT] before it
 * rethrows.
 */
internal suspend fun <I, O, T> MavlinkVehicle.run(
    machine: ProtocolMachine<I, O, T>,
    wire: Wire<I, O>,
    afterStep: () -> Unit = {},
): T {
    val origin = clock.markNow()
    fun now() = origin.elapsedNow().inWholeNanoseconds
    val watch = ExchangeWatch(this, wire.during, wire.giveUpAfter)
    val exchange = InPlaceExchange(this, machine, wire, watch, afterStep, ::now)
    val untap = tap { inbound -> wire.pick(inbound)?.let { exchange.feed(it, answer = wire.isAnswer(it)) } }
    val untapTexts = wire.texts?.let { read -> tapTexts { line -> read(line)?.let { exchange.feed(it, answer = false) } } }
    val unwatchLoss = onLost { exchange.lost(VehicleLost(systemId, wire.during)) }
    try {
        exchange.start()
        while (true) {
            for (message in exchange.takeUnsent()) send(wire.encode(message))
            exchange.outcome?.let { outcome ->
                when (outcome) {
                    is Outcome.Done -> return outcome.value
                    is Outcome.Failed -> throw outcome.error
                }
            }
            val timer = exchange.wakeAt
            if (HotWait.poll(exchange.wake, minOf(wire.hotWaitNanos(), timer - now()))) continue
            val woken = if (timer == Step.NEVER) {
                exchange.wake.await()
            } else {
                withTimeoutOrNull((timer - now()).coerceAtLeast(0).nanoseconds) { exchange.wake.await() }
            }
            if (woken == null) exchange.timerExpired()
        }
        @Suppress("UNREACHABLE_CODE")
        error("unreachable")
    } catch (e: CancellationException) {
        untap() // nothing more is fed to the machine
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

/**
 * One exchange's machine and what it asked for, shared by the receive path ([feed]) and the
 * driving coroutine ([start], [timerExpired]) under one lock. [wake] tells the coroutine that the
 * outcome is in, the timer moved earlier, or messages wait to be sent by it; it is closed with
 * [VehicleLost] when the vehicle is lost.
 */
private class InPlaceExchange<I, O, T>(
    private val vehicle: MavlinkVehicle,
    private val machine: ProtocolMachine<I, O, T>,
    private val wire: Wire<I, O>,
    private val watch: ExchangeWatch,
    private val afterStep: () -> Unit,
    private val now: () -> Long,
) {
    val wake = Doorbell()
    private val unsent = ArrayList<O>()

    @Volatile var wakeAt: Long = Step.NEVER
        private set

    @Volatile var outcome: Outcome<T>? = null
        private set

    fun start() = synchronized(this) { apply(machine.start(now())) }

    fun feed(input: I, answer: Boolean) {
        if (answer) watch.answered()
        synchronized(this) {
            if (outcome == null) apply(machine.onMessage(input, now()))
        }
    }

    fun timerExpired() = synchronized(this) {
        val at = now()
        if (outcome == null && wakeAt != Step.NEVER && at >= wakeAt) apply(machine.onTimer(at))
    }

    fun lost(error: VehicleLost) {
        wake.close(error)
    }

    fun takeUnsent(): List<O> = synchronized(this) {
        if (unsent.isEmpty()) emptyList() else unsent.toList().also { unsent.clear() }
    }

    /** Carries out [step]: sends in place if it can, else leaves the messages to the coroutine. */
    private fun apply(step: Step<O, T>) {
        var ping = false
        for (message in step.send) {
            if (unsent.isNotEmpty() || !vehicle.station.sendNow(vehicle, wire.encode(message))) {
                unsent += message
                ping = true
            }
        }
        if (step.send.isNotEmpty()) watch.sent()
        if (step.wakeAt != Step.KEEP) {
            if (step.wakeAt < wakeAt) ping = true
            wakeAt = step.wakeAt
        }
        afterStep()
        if (step.outcome != null) {
            outcome = step.outcome
            ping = true
        }
        if (ping) wake.ring()
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
