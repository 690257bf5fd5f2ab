package pod.mavlink.action

import pod.core.units.Distance
import pod.core.vehicle.LandedState
import pod.mavlink.MavFrames
import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.MavCommands
import pod.mavlink.mission.MissionItem
import pod.mavlink.plan.LandingApproach
import kotlin.math.roundToInt

/**
 * A landing for an ArduPlane in flight that holds no landing sequence (DO_LAND_START answered
 * FAILED with "No landing sequence found": ArduPlane's DO_LAND_START handler switches to AUTO only
 * when libraries/AP_Mission/AP_Mission.cpp, `AP_Mission::jump_to_landing_sequence`, finds a
 * DO_LAND_START in the mission, and that function sends the text when it finds none): the same approach the mission executor plans before a plane's landing
 * ([LandingApproach]: a waypoint about 343 m out at 30 m, into the line from where the plane is),
 * then NAV_LAND at home, uploaded in place of the mission on board and flown in AUTO from the approach.
 */
internal object PlaneLanding {
    /** Uploads [home item, approach, land at home] to [vehicle] and sets item 1 current; the caller switches to AUTO. */
    suspend fun plan(vehicle: MavlinkVehicle) {
        val t = vehicle.telemetry
        val home = t.home.value ?: throw ActionUnsupported("land", "no landing sequence on board, and no home to land at yet")
        val here = t.position.value ?: throw ActionUnsupported("land", "no landing sequence on board, and no position to plan an approach from")
        if (t.landedState.value == LandedState.ON_GROUND) throw ActionUnsupported("land", "vehicle ${vehicle.systemId} is on the ground")
        val from = here.location.copy(altitude = here.relativeAltitude)
        val approach = LandingApproach.point(home.copy(altitude = Distance.ZERO), from, heading = null, lastCourse = here.heading?.degrees)
        vehicle.mission.upload(
            listOf(
                item(0, MavFrames.GLOBAL, MavCommands.NAV_WAYPOINT, home.latitude, home.longitude, home.altitude.meters),
                item(1, MavFrames.GLOBAL_RELATIVE_ALT, MavCommands.NAV_WAYPOINT, approach.latitude, approach.longitude, approach.altitude.meters),
                item(2, MavFrames.GLOBAL_RELATIVE_ALT, MavCommands.NAV_LAND, home.latitude, home.longitude, 0.0),
            ),
        )
        vehicle.mission.setCurrent(1)
    }

    private fun item(seq: Int, frame: Int, command: Int, lat: Double, lon: Double, alt: Double) = MissionItem(
        seq, frame, command, x = (lat * 1e7).roundToInt(), y = (lon * 1e7).roundToInt(), z = alt.toFloat(),
    )
}
