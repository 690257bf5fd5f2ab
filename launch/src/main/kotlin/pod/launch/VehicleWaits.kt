package pod.launch

import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.distinctUntilChanged
import kotlinx.coroutines.flow.distinctUntilChangedBy
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.launch
import pod.mavlink.GroundStation

/**
 * Says, for every vehicle [station] hears, what a program is waiting for from it, each new reason
 * once, as the vehicle commands do: a refusal that clears by waiting ("vehicle 1: waiting: Arm:
 * Need Position Estimate", [pod.mavlink.action.VehicleActions.waitingFor]) and an exchange the
 * vehicle leaves unanswered ([pod.mavlink.MavlinkVehicle.awaiting]). Runs until cancelled.
 */
internal suspend fun showWaits(station: GroundStation, print: (String) -> Unit): Unit = coroutineScope {
    val watched = HashSet<Int>()
    station.vehicles.collect { heard ->
        for (v in heard.values) {
            if (!watched.add(v.systemId)) continue
            launch { v.action.waitingFor.filterNotNull().distinctUntilChanged().collect { print("vehicle ${v.systemId}: waiting: $it") } }
            launch { v.awaiting.filterNotNull().distinctUntilChangedBy { it.what }.collect { print(it.describe()) } }
        }
    }
}
