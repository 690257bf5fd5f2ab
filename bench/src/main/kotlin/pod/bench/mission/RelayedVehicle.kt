package pod.bench.mission

import kotlinx.coroutines.CoroutineScope
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import pod.sim.fault.LinkFaults
import pod.sim.fault.LossyRelay
import java.net.DatagramSocket
import java.net.InetAddress

/** The simulated vehicle's system id in every run. */
const val VEHICLE_SYSTEM_ID = 21

/**
 * A fresh simulated vehicle of [cell]'s flavour behind a fresh relay that drops [Cell.loss] of the
 * datagrams each way (nothing else), seeded with [seed], sending to a ground station listening on
 * loopback port [gcsPort]. Both live in [scope] until [close].
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
        suspend fun start(scope: CoroutineScope, cell: Cell, seed: Long, gcsPort: Int): RelayedVehicle {
            val faults = LinkFaults(drop = cell.loss)
            val relay = LossyRelay("udpin://127.0.0.1:0", "udpout://127.0.0.1:$gcsPort", faults, faults, seed = seed)
            relay.start(scope)
            val sim = SimVehicle(SimVehicleConfig(systemId = VEHICLE_SYSTEM_ID, autopilot = cell.flavour, gcs = "udpout://127.0.0.1:${relay.portA}"))
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
