package pod.e2e

import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import pod.mavlink.GroundStation
import pod.mavlink.MavlinkVehicle

/** Suspends until [count] vehicles are known and each has reported a position. */
internal suspend fun GroundStation.awaitFleetWithPositions(count: Int): Map<Int, MavlinkVehicle> {
    val fleet = vehicles.first { it.size >= count }
    fleet.values.forEach { it.telemetry.position.filterNotNull().first() }
    return fleet
}
