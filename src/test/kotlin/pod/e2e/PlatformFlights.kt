package pod.e2e

import kotlin.math.roundToLong
import kotlinx.coroutines.async
import pod.core.units.Location
import pod.core.platform.PlatformVehicle
import pod.core.units.m
import pod.dsl.mission

/** [this] moved [north] and [east] metres at [height] above home, on the wire's 10⁻⁷° grid. */
internal fun Location.at(north: Int, east: Int, height: Double): Location =
    offset(north.m, east.m).let { Location((it.latitude * 1e7).roundToLong() / 1e7, (it.longitude * 1e7).roundToLong() / 1e7, height.m) }

/**
 * Flies [mission], which ends in an unlimited loiter, until [vehicle] reports itself established
 * on it ([pod.core.platform.MissionEvent.Loitering]), then cancels the run, as a program's `until`
 * would; fails if the run ends by itself first (such a mission runs until cancelled).
 */
internal suspend fun pod.core.platform.Platform.flyUntilLoitering(
    vehicle: pod.core.platform.PlatformVehicle,
    mission: pod.core.mission.Mission,
    report: (pod.core.platform.MissionEvent) -> Unit = {},
): Unit = kotlinx.coroutines.coroutineScope {
    val loitering = kotlinx.coroutines.CompletableDeferred<Unit>()
    val run = async {
        fly(vehicle, mission).collect {
            report(it)
            if (it is pod.core.platform.MissionEvent.Loitering) loitering.complete(Unit)
        }
    }
    kotlinx.coroutines.selects.select<Unit> {
        loitering.onAwait { run.cancel() }
        run.onAwait { error("the run of \"${mission.name}\" ended by itself; a mission ending in an unlimited loiter runs until cancelled") }
    }
}

/** A plane's circuit from [v]'s home: take off, fly 500 m out climbing 20 m, come back over home and land. */
internal fun circuit(v: PlatformVehicle) = mission("circuit ${v.name}") {
    home(v.home.value!!)
    takeOff(40.m)
    move(north = 500.m, up = 20.m)
    returnHomeAndLand()
}
