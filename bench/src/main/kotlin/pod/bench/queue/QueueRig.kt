package pod.bench.queue

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import pod.bench.RelayedVehicle
import pod.core.units.Distance
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.mavlink.GroundStation
import pod.mavlink.GroundStationConfig
import pod.mavlink.MavlinkVehicle
import pod.sim.SimVehicle
import pod.sim.SimVehicleConfig
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds

/** The simulated vehicle's system id. */
const val QUEUE_VEHICLE_ID = 31

/** Height above home the vehicle flies at, every target included. */
val FLIGHT_HEIGHT = 20.m

/**
 * A Pod ground station on loopback and one simulated vehicle flying at [FLIGHT_HEIGHT], straight or
 * through a relay, in real time (time scale 1): the station's [vehicle], the simulator's [sim] (the
 * vehicle side, watched), and [home].
 */
class QueueRig private constructor(
    val gcs: GroundStation,
    val sim: SimVehicle,
    private val relay: RelayedVehicle?,
    val vehicle: MavlinkVehicle,
    val home: Location,
) : AutoCloseable {
    override fun close() {
        relay?.close() ?: sim.stop()
        gcs.close()
    }

    companion object {
        /** Starts both ends in [scope] under [condition], arms and takes off to [height]; bounded (each step by its own timeout). */
        suspend fun airborne(scope: CoroutineScope, flavour: Autopilot, condition: LinkCondition, seed: Long, height: Distance = FLIGHT_HEIGHT): QueueRig {
            // Heartbeats cross the lossy relay too: several in a row go missing now and then at 20 %.
            val gcs = GroundStation.open("udpin://127.0.0.1:0", scope, GroundStationConfig(lostAfter = 30.seconds))
            val config = SimVehicleConfig(systemId = QUEUE_VEHICLE_ID, autopilot = flavour, timeScale = 1.0)
            var relay: RelayedVehicle? = null
            val sim: SimVehicle
            try {
                val faults = condition.faults
                if (faults == null) {
                    sim = SimVehicle(config.copy(gcs = "udpout://127.0.0.1:${gcs.link.localPort}"))
                    sim.start(scope)
                } else {
                    relay = RelayedVehicle.start(scope, config, faults, seed, gcs.link.localPort)
                    sim = relay.sim
                }
            } catch (e: Throwable) {
                gcs.close()
                throw e
            }
            val rig = try {
                val vehicle = withTimeout(30.seconds) { gcs.vehicles.first { QUEUE_VEHICLE_ID in it } }.getValue(QUEUE_VEHICLE_ID)
                withTimeout(30.seconds) { vehicle.telemetry.gps.first { it?.has3dFix == true } }
                val home = withTimeout(30.seconds) { vehicle.telemetry.home.filterNotNull().first() }
                QueueRig(gcs, sim, relay, vehicle, home)
            } catch (e: Throwable) {
                relay?.close() ?: sim.stop()
                gcs.close()
                throw e
            }
            try {
                withTimeout(2.minutes) {
                    rig.vehicle.action.arm()
                    rig.vehicle.action.takeoff(height)
                }
            } catch (e: Throwable) {
                rig.close()
                throw e
            }
            return rig
        }
    }
}
