package pod.cli

import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeoutOrNull
import pod.mavlink.MavlinkVehicle
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionType
import pod.mavlink.plan.PlanOnVehicle
import pod.mavlink.plan.QgcPlan
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * The plan of the MISSION, FENCE and RALLY [lists] downloaded from [vehicle] (`pod mission download
 * x.plan`, the ground station's plans): what the vehicle tells of itself goes in (autopilot,
 * airframe, and its home, waited for at most [homeWait]); what it does not is left out, never
 * written as 0. ArduPilot's mission item 0 is its home, the plan's planned home.
 *
 * @throws pod.mavlink.plan.PlanListException when the fence or rally list describes no fence or rally points.
 */
internal suspend fun planOf(vehicle: MavlinkVehicle, lists: Map<MissionType, List<MissionItem>>, homeWait: Duration = 5.seconds): QgcPlan {
    val identity = vehicle.identity.value
    // The station asks for HOME_POSITION on discovery; a vehicle that has a home answers within a moment.
    val home = withTimeoutOrNull(homeWait) { vehicle.telemetry.home.filterNotNull().first() }
    return PlanOnVehicle.plan(
        lists[MissionType.MISSION].orEmpty(), lists[MissionType.FENCE].orEmpty(), lists[MissionType.RALLY].orEmpty(),
        identity.autopilot, identity.type, home,
    )
}
