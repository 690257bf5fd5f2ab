package pod.sim.autopilot

import pod.mavlink.telemetry.Px4CustomMode
import pod.mavlink.command.MavCommands
import pod.mavlink.command.CommandResult
import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Autopilot
import pod.core.vehicle.VehicleType
import pod.mavlink.mission.MissionItem
import pod.mavlink.vehicle.MissionServer
import pod.mavlink.vehicle.MissionServerFlavor
import pod.mavlink.mission.MissionType
import pod.sim.SimVehicleConfig
import kotlin.math.roundToLong

internal val HOME: Location = SimVehicleConfig.DEFAULT_HOME

/** A simulated autopilot of the given flavour at [HOME], with its GPS ready after 2 s. */
internal fun autopilot(autopilot: Autopilot = Autopilot.ARDUPILOT, type: VehicleType = VehicleType.QUADROTOR, charge: Double = 1.0): SimAutopilot {
    lateinit var ap: SimAutopilot
    ap = SimAutopilot(
        autopilot, type, 1, HOME, charge,
        MissionServer(if (autopilot == Autopilot.PX4) MissionServerFlavor.PX4 else MissionServerFlavor.ARDUPILOT, clearAllowed = { ap.allowsClearing(it) }),
        readyAfter = 2.0,
    )
    return ap
}

internal const val DT = 0.05

/** Steps simulated time until [done] holds; fails after [limit] simulated seconds. */
internal fun SimAutopilot.runUntil(limit: Double, check: (SimAutopilot) -> Unit = {}, done: (SimAutopilot) -> Boolean) {
    val end = time + limit
    while (!done(this)) {
        check(time < end) { "not done after $limit simulated seconds (t=$time, mode=$modeName, activity=$activity, at ${body.location}, armed=$armed)" }
        step(DT)
        check(this)
    }
}

/** Steps [seconds] of simulated time. */
internal fun SimAutopilot.run(seconds: Double, check: (SimAutopilot) -> Unit = {}) {
    val end = time + seconds
    while (time < end - 1e-9) {
        step(DT)
        check(this)
    }
}

/** Sends [cmd] and returns its COMMAND_ACK result (the others it queued stay readable via [outputs]). */
internal fun SimAutopilot.command(cmd: CommandRequest, outputs: MutableList<SimOutput>? = null): CommandResult {
    commands.handle(cmd)
    val out = drain()
    outputs?.addAll(out)
    return out.filterIsInstance<SimOutput.Ack>().last { it.command == cmd.command }.result
}

internal fun SimAutopilot.armCommand(): CommandResult = command(CommandRequest(MavCommands.COMPONENT_ARM_DISARM, param1 = 1f))

internal fun SimAutopilot.mode(name: String): CommandResult {
    val custom = pod.mavlink.telemetry.FlightModes.customMode(autopilot, type, name)!!
    return if (profile is pod.sim.autopilot.profile.Px4Profile) {
        command(CommandRequest(MavCommands.DO_SET_MODE, param1 = 1f, param2 = Px4CustomMode.main(custom).toFloat(), param3 = Px4CustomMode.sub(custom).toFloat()))
    } else {
        command(CommandRequest(MavCommands.DO_SET_MODE, param1 = 1f, param2 = custom.toFloat()))
    }
}

/** Loads [items] as the MISSION list. */
internal fun SimAutopilot.load(items: List<MissionItem>) = missionServer.load(MissionType.MISSION, items)

/** A mission item at [north]/[east] metres from [HOME], [alt] metres above home. */
internal fun item(command: Int, north: Double = 0.0, east: Double = 0.0, alt: Double = 0.0, p1: Float = 0f, p2: Float = 0f, p3: Float = 0f, global: Boolean = true, x: Int? = null): MissionItem {
    val at = HOME.offset(north = north.m, east = east.m)
    return MissionItem(
        seq = 0, frame = if (global) 3 else 2, command = command, param1 = p1, param2 = p2, param3 = p3,
        x = x ?: if (global) (at.latitude * 1e7).roundToLong().toInt() else 0,
        y = if (global) (at.longitude * 1e7).roundToLong().toInt() else 0,
        z = alt.toFloat(),
    )
}

/** ArduPilot's item 0: home. */
internal fun homeItem(): MissionItem = item(16, alt = 0.0).copy(frame = 0, z = HOME.altitude.meters.toFloat())
