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

/**
 * Runs one protocol exchange with this vehicle: [block] reads the messages [pick] keeps from
 * everything the vehicle sends, in order and without loss; the channel fails with [VehicleLost]
 * (naming [during]) as soon as the vehicle is marked lost. Listening starts before [block] runs,
 * so a reply to its first send cannot slip past.
 */
internal suspend fun <T, R> MavlinkVehicle.exchange(
    during: String,
    pick: (InboundMessage) -> T?,
    block: suspend CoroutineScope.(ReceiveChannel<T>) -> R,
): R = coroutineScope {
    val inbox = Channel<T>(Channel.UNLIMITED)
    val listening = launch(start = CoroutineStart.UNDISPATCHED) {
        messages.collect { inbound -> pick(inbound)?.let { inbox.trySend(it) } }
    }
    val lost = launch(start = CoroutineStart.UNDISPATCHED) {
        connection.first { it == ConnectionState.LOST }
        inbox.close(VehicleLost(systemId, during))
    }
    try {
        block(inbox)
    } finally {
        listening.cancel()
        lost.cancel()
    }
}
