package pod.bench

import kotlinx.coroutines.CoroutineScope
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import pod.sim.fault.LossyRelay
import java.net.DatagramSocket
import java.net.InetAddress

/**
 * A fresh simulated vehicle behind its own fresh relay that drops [loss] of the datagrams each
 * way (nothing else), seeded, sending to a ground station listening on loopback. Both live in the
 * scope given to [start] until [close]. One relay per vehicle, as each vehicle has its own radio.
 */
class RelayedVehicle private constructor(val sim: SimVehicle, val relay: LossyRelay) : AutoCloseable {
    /** Datagrams dropped on the way to the ground station. */
    val droppedToGcs: Long get() = relay.counters.value.aToB.dropped

    /** Datagrams dropped on the way to the vehicle. */
    val droppedToVehicle: Long get() = relay.counters.value.bToA.dropped

    override fun close() {
        sim.stop()
        relay.close()
    }

    companion object {
        /**
         * Starts a relay with [loss] (0..1) each way, seeded with [seed], towards loopback port
         * [gcsPort], and a vehicle of [config] (its `gcs` replaced by the relay's address) behind it.
         */
        suspend fun start(scope: CoroutineScope, config: SimVehicleConfig, loss: Double, seed: Long, gcsPort: Int): RelayedVehicle =
            start(scope, config, LinkFaults(drop = loss), seed, gcsPort)

        /** As the other [start], with any [faults] (the same each way): a delay, loss, … */
        suspend fun start(scope: CoroutineScope, config: SimVehicleConfig, faults: LinkFaults, seed: Long, gcsPort: Int): RelayedVehicle {
            val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:$gcsPort", faults, faults, seed = seed)
            relay.start(scope)
            val sim = SimVehicle(config.copy(gcs = "udpout://127.0.0.1:${relay.portA}"))
            try {
                sim.start(scope)
            } catch (e: Throwable) {
                relay.close()
                throw e
            }
            return RelayedVehicle(sim, relay)
        }
    }
}

/** A UDP port on loopback that was free a moment ago (MAVSDK cannot report the port it bound). */
fun freeUdpPort(): Int = DatagramSocket(0, InetAddress.getLoopbackAddress()).use { it.localPort }
