package pod.mavlink.plan

import kotlin.math.roundToInt
import kotlin.time.Duration.Companion.seconds
import pod.core.mission.LoiterDuration
import pod.core.mission.Mission
import pod.core.mission.MissionStep
import pod.core.mission.PrecisionLand
import pod.mavlink.command.SpeedTypes
import pod.core.units.Location
import pod.core.units.deg
import pod.core.units.m
import pod.core.units.mps
import pod.mavlink.command.MavCommands
import pod.mavlink.mission.MissionItem

/**
 * Reads mission items (as downloaded from a vehicle) back into protocol-neutral mission steps: the
 * inverse of [MissionPlanner] for the steps a flavour takes as items.
 *
 * Steps that do not come back as they went: a [MissionStep.ChangeAltitude] planned as a waypoint
 * (ArduCopter, PX4) reads as that waypoint; loiter turns planned as a timed loiter (PX4) read as
 * the timed loiter; a multirotor's take-off pitch (not sent) reads as 0°; steps sent as commands
 * are not on the vehicle at all.
 */
public object MissionReader {
    /**
     * The steps [items] describe for [flavor] (ArduPilot's item 0, home, and ArduPlane's
     * DO_LAND_START markers are not steps). Throws [UnsupportedMissionItem] for an item that is not
     * one of the commands [MissionPlanner] writes.
     */
    public fun steps(items: List<MissionItem>, flavor: MissionFlavor): List<MissionStep> =
        items.drop(if (flavor.homeAtZero) 1 else 0)
            .filterNot { flavor.landStartIsMarker && it.command == MavCommands.DO_LAND_START }
            .map(::step)

    /**
     * The mission [items] describe for [flavor], named [name]; its home is ArduPilot's item 0 (null
     * on PX4, whose list carries no home).
     */
    public fun mission(name: String, items: List<MissionItem>, flavor: MissionFlavor): Mission {
        val home = if (flavor.homeAtZero) items.firstOrNull()?.let { Location(it.latitude, it.longitude, it.z.toDouble().m) } else null
        return Mission(name, home, steps(items, flavor))
    }

    private fun step(item: MissionItem): MissionStep = when (item.command) {
        MavCommands.NAV_TAKEOFF -> MissionStep.TakeOff(item.location(), item.param1.toDouble().deg)
        MavCommands.NAV_WAYPOINT -> MissionStep.Waypoint(item.location(), item.param1.toDouble().seconds)
        MavCommands.NAV_LOITER_UNLIM -> MissionStep.Loiter(item.location(), item.param3.toDouble().m, LoiterDuration.Unlimited)
        MavCommands.NAV_LOITER_TURNS -> MissionStep.Loiter(item.location(), item.param3.toDouble().m, LoiterDuration.Turns(item.param1.roundToInt()))
        MavCommands.NAV_LOITER_TIME -> MissionStep.Loiter(item.location(), item.param3.toDouble().m, LoiterDuration.Time(item.param1.toDouble().seconds))
        MavCommands.NAV_LAND -> MissionStep.Land(
            item.location(),
            yaw = item.param4.takeUnless { it.isNaN() }?.toDouble()?.deg,
            precision = when (item.param2.roundToInt()) {
                1 -> PrecisionLand.OPPORTUNISTIC
                2 -> PrecisionLand.REQUIRED
                else -> PrecisionLand.DISABLED
            },
        )
        MavCommands.NAV_RETURN_TO_LAUNCH -> MissionStep.ReturnHome
        MavCommands.DO_CHANGE_SPEED -> MissionStep.ChangeSpeed(
            SpeedTypes.kindOf(item.param1.roundToInt()),
            item.param2.toDouble().mps,
        )
        MavCommands.NAV_CONTINUE_AND_CHANGE_ALT -> MissionStep.ChangeAltitude(item.z.toDouble().m)
        MavCommands.NAV_DELAY -> MissionStep.Delay(item.param1.toDouble().seconds)
        MavCommands.IMAGE_START_CAPTURE -> MissionStep.StartCapture(item.param3.roundToInt(), item.param2.toDouble().seconds)
        MavCommands.IMAGE_STOP_CAPTURE -> MissionStep.StopCapture
        else -> throw UnsupportedMissionItem(item)
    }

    private fun MissionItem.location(): Location = Location(latitude, longitude, z.toDouble().m)
}

/** A mission item Pod cannot read as a mission step ([MissionReader] knows the commands [MissionPlanner] writes). */
public class UnsupportedMissionItem(
    /** The item that could not be read, as the vehicle stores it. */
    public val item: MissionItem,
) : pod.core.PodException("mission item ${item.seq} (MAV_CMD ${item.command}) is not a step Pod can read")
