package pod.mavlink

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.channels.ReceiveChannel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import pod.core.vehicle.ConnectionState
import pod.core.vehicle.VehicleLost
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * Runs one protocol exchange with this vehicle: [block] reads the messages [pick] keeps from
 * everything the vehicle sends, in order and without loss; the channel fails with [VehicleLost]
 * (naming [during]) as soon as the vehicle is marked lost. Listening starts before [block] runs,
 * so a reply to its first send cannot slip past.
 *
 * [block] calls [ExchangeWatch.sent] after each request it sends: once the vehicle has left the
 * exchange unanswered for [ExchangeWatch.QUIET], [MavlinkVehicle.awaiting] says so (with
 * [giveUpAfter], the silence after which the exchange fails) until an answer comes or it ends.
 */
internal suspend fun <T, R> MavlinkVehicle.exchange(
    during: String,
    pick: (InboundMessage) -> T?,
    giveUpAfter: Duration? = null,
    block: suspend CoroutineScope.(ReceiveChannel<T>, ExchangeWatch) -> R,
): R = coroutineScope {
    val inbox = Channel<T>(Channel.UNLIMITED)
    val watch = ExchangeWatch(this@exchange, during, giveUpAfter)
    val listening = launch(start = CoroutineStart.UNDISPATCHED) {
        messages.collect { inbound ->
            pick(inbound)?.let {
                watch.answered()
                inbox.trySend(it)
            }
        }
    }
    val lost = launch(start = CoroutineStart.UNDISPATCHED) {
        connection.first { it == ConnectionState.LOST }
        inbox.close(VehicleLost(systemId, during))
    }
    try {
        block(inbox, watch)
    } finally {
        listening.cancel()
        lost.cancel()
        watch.ended()
    }
}

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
