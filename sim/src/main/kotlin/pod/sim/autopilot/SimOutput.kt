package pod.sim.autopilot

import pod.mavlink.command.CommandResult
import pod.core.vehicle.Severity
import pod.sim.PhotoEvent

/** What the simulated autopilot wants sent, in order; the vehicle's coroutine glue encodes it. */
internal sealed interface SimOutput {
    /** COMMAND_ACK to the sender of a command. */
    data class Ack(val command: Int, val result: CommandResult, val progress: Int, val targetSystem: Int, val targetComponent: Int) : SimOutput

    /** STATUSTEXT with MAV_SEVERITY [severity]. */
    data class Text(val severity: Severity, val text: String) : SimOutput

    /** MISSION_ITEM_REACHED. */
    data class ItemReached(val seq: Int) : SimOutput

    /** MISSION_CURRENT after a change of the current item. */
    data class MissionCurrent(val seq: Int) : SimOutput

    /** CAMERA_IMAGE_CAPTURED for a photo just taken. */
    data class Photo(val photo: PhotoEvent) : SimOutput

    /** HOME_POSITION, because home moved. */
    data object HomeChanged : SimOutput

    /** PARAM_VALUE for the parameter at [index]. */
    data class Param(val index: Int) : SimOutput

    /**
     * FENCE_STATUS (162): [breached] now, breaches so far, FENCE_BREACH [type], when the breach
     * began (ms since boot), FENCE_MITIGATE [mitigation].
     */
    data class FenceStatus(val breached: Boolean, val count: Int, val type: Int, val timeMs: Long, val mitigation: Int) : SimOutput
}

/** A COMMAND_LONG or COMMAND_INT, normalised: [frame] is null for COMMAND_LONG. */
internal data class CommandRequest(
    val command: Int,
    val param1: Float = 0f,
    val param2: Float = 0f,
    val param3: Float = 0f,
    val param4: Float = 0f,
    /** param5 of COMMAND_LONG, or x of COMMAND_INT as a number. */
    val x: Double = 0.0,
    /** param6 of COMMAND_LONG, or y of COMMAND_INT. */
    val y: Double = 0.0,
    /** param7 / z. */
    val z: Float = 0f,
    val frame: Int? = null,
    val confirmation: Int = 0,
    val sourceSystem: Int = 255,
    val sourceComponent: Int = 190,
) {
    /** True for COMMAND_INT. */
    val isInt: Boolean get() = frame != null

    /** Latitude in degrees from param5 / x, or null when it says "unchanged" (NaN, INT32_MAX). */
    fun latitude(): Double? = coordinate(x)

    /** Longitude in degrees from param6 / y, or null when it says "unchanged". */
    fun longitude(): Double? = coordinate(y)

    private fun coordinate(v: Double): Double? = when {
        v.isNaN() -> null
        isInt -> if (v == Int.MAX_VALUE.toDouble()) null else v / 1e7
        else -> v
    }
}

/** Pack voltage of the simulated 4S battery at [charge] (3.5 V per cell empty, 4.2 V full). */
internal fun packVoltage(charge: Double): Double = 4 * (3.5 + 0.7 * charge)
