package pod.e2e

import kotlin.math.roundToLong
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.coroutineScope
import pod.core.platform.PlatformVehicle
import pod.core.units.Location
import pod.core.units.m
import pod.mavlink.MavlinkVehicle
import pod.sim.SimFlavor
import pod.sim.SimPlatform
import pod.sim.SimVehicle

/** One simulated vehicle of [flavor] on a fresh platform at [timeScale]× speed; everything stops afterwards. */
internal suspend fun withVehicle(
    flavor: SimFlavor,
    timeScale: Double = 20.0,
    block: suspend CoroutineScope.(SimPlatform, PlatformVehicle, MavlinkVehicle, SimVehicle) -> Unit,
) = coroutineScope {
    val fleet = SimPlatform.start(this, listOf(flavor), timeScale = timeScale)
    try {
        val v = fleet.vehicles.value.single()
        block(fleet, v, fleet.platform.mavlink(v), fleet.simulated.single())
    } finally {
        fleet.close()
    }
}

/** [this] moved [north] and [east] metres at [height] above home, on the wire's 10⁻⁷° grid. */
internal fun Location.at(north: Int, east: Int, height: Double): Location =
    offset(north.m, east.m).let { Location((it.latitude * 1e7).roundToLong() / 1e7, (it.longitude * 1e7).roundToLong() / 1e7, height.m) }
