package pod.sim

import pod.core.units.Location
import pod.mavlink.MavFrames
import pod.mavlink.command.MavCommands
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionMessage
import pod.mavlink.protocol.Step
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.VehicleMachine
import pod.sim.autopilot.SimAutopilot
import pod.sim.autopilot.profile.AutopilotProfile
import kotlin.math.roundToLong

/**
 * The simulated vehicle's side of the mission protocol as [pod.mavlink.vehicle.serve] drives it:
 * each message goes through the autopilot, which hands it to its mission server and reacts to
 * the list as it is afterwards ([SimAutopilot.onMissionMessage]); the timer (re-requests, giving
 * up on a silent upload) is the server's alone.
 */
internal class VehicleMissions(private val autopilot: SimAutopilot) : VehicleMachine<MissionMessage, MissionMessage> {
    override fun onMessage(message: MissionMessage, now: Long): Step<MissionMessage, Nothing> = autopilot.onMissionMessage(message, now)

    override fun onTimer(now: Long): Step<MissionMessage, Nothing> = autopilot.missionServer.onTimer(now)

    companion object {
        /**
         * The mission server of a vehicle configured by [config], behaving as its autopilot does.
         * Its clock is the vehicle's Timebase since boot, not simulated time, so the storage delay
         * the configuration gives in simulated time is scaled; home and whether a list may be
         * cleared come from the [autopilot] as it is when a message asks.
         */
        fun server(config: SimVehicleConfig, autopilot: () -> SimAutopilot): MissionServer = MissionServer(
            // The firmware's mission protocol and storage form, as its profile says.
            AutopilotProfile.of(config.autopilot, config.type).missionServerFlavor,
            fixedWing = AutopilotProfile.of(config.autopilot, config.type).missionServerFixedWing,
            storageReadyAt = (config.missionStorageReadyAfter / config.timeScale).inWholeNanoseconds,
            home = { homeItem(autopilot().home) },
            clearAllowed = { type -> autopilot().allowsClearing(type) },
        )

        /** [home] as the NAV_WAYPOINT an ArduPilot-flavoured server writes over item 0. */
        private fun homeItem(home: Location): MissionItem = MissionItem(
            seq = 0, frame = MavFrames.GLOBAL, command = MavCommands.NAV_WAYPOINT,
            x = (home.latitude * 1e7).roundToLong().toInt(), y = (home.longitude * 1e7).roundToLong().toInt(),
            z = home.altitude.meters.toFloat(),
        )
    }
}
