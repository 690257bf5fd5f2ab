package pod.mavlink.mission

import kotlin.math.abs
import pod.mavlink.MavFrames
import pod.mavlink.command.MavCommands.CONDITION_DELAY
import pod.mavlink.command.MavCommands.CONDITION_YAW
import pod.mavlink.command.MavCommands.DO_CHANGE_SPEED
import pod.mavlink.command.MavCommands.DO_JUMP
import pod.mavlink.command.MavCommands.DO_LAND_START
import pod.mavlink.command.MavCommands.DO_SET_CAM_TRIGG_DIST
import pod.mavlink.command.MavCommands.DO_SET_HOME
import pod.mavlink.command.MavCommands.DO_SET_SERVO
import pod.mavlink.command.MavCommands.NAV_CONTINUE_AND_CHANGE_ALT
import pod.mavlink.command.MavCommands.NAV_DELAY
import pod.mavlink.command.MavCommands.NAV_LAND
import pod.mavlink.command.MavCommands.NAV_LOITER_TIME
import pod.mavlink.command.MavCommands.NAV_LOITER_TO_ALT
import pod.mavlink.command.MavCommands.NAV_LOITER_TURNS
import pod.mavlink.command.MavCommands.NAV_LOITER_UNLIM
import pod.mavlink.command.MavCommands.NAV_RETURN_TO_LAUNCH
import pod.mavlink.command.MavCommands.NAV_SPLINE_WAYPOINT
import pod.mavlink.command.MavCommands.NAV_TAKEOFF
import pod.mavlink.command.MavCommands.NAV_VTOL_LAND
import pod.mavlink.command.MavCommands.NAV_VTOL_TAKEOFF
import pod.mavlink.command.MavCommands.NAV_WAYPOINT

/**
 * What ArduPilot keeps of a mission item: it does not store MISSION_ITEM_INT as sent but packs
 * each command into a 15-byte record (a 16-bit `p1` and 12 bytes of command-specific content, or
 * a location) and rebuilds the item from that record when asked. A download therefore returns
 * its own form of what was uploaded:
 * - parameters the command does not store come back 0 (a NaN yaw too; the acceptance radius of a
 *   copter NAV_WAYPOINT, which keeps only the delay in `p1`);
 * - parameters stored as integers come back truncated (a NAV_WAYPOINT delay of 2.5 s is 2);
 * - NAV_LOITER_TIME keeps only the turning direction, so any radius comes back ±1;
 * - commands without a location come back in frame 0 with x, y and z 0;
 * - altitudes are kept in whole centimetres, frames reduced to MSL (0), relative (3) or terrain (10);
 * - fence and rally items come back with autocontinue 0 (they are kept as points, not commands);
 * - item 0 of a mission is the vehicle's home (see [pod.mavlink.vehicle.MissionServer.home]).
 *
 * Derived from ArduPilot's libraries/AP_Mission/AP_Mission.cpp: `mavlink_int_to_mission_cmd`
 * (what is stored), `mission_cmd_to_mavlink_int` (what is sent back, with every param defaulting
 * to 0 and autocontinue to 1), `stored_in_location` (which commands carry a location) and
 * `sanity_check_params` (which params may be NaN). Commands that function does not know are
 * refused by ArduPilot (MAV_MISSION_UNSUPPORTED); here they are kept as sent, so the simulator
 * stays usable with commands Pod does not model.
 */
public object ArduPilotMissionStorage {

    /** The item as ArduPilot would send it back after storing it; [fixedWing] for ArduPlane. */
    public fun stored(item: MissionItem, fixedWing: Boolean): MissionItem {
        if (item.missionType != MissionType.MISSION) {
            // AC_PolyFence_loader / AP_Rally keep points; both answer downloads with autocontinue 0.
            return item.copy(current = false, autocontinue = false)
        }
        val p = params(item, fixedWing) ?: return item.copy(current = false)
        val base = item.copy(current = false, autocontinue = true, param1 = p[0], param2 = p[1], param3 = p[2], param4 = p[3])
        return if (item.command in LOCATION_COMMANDS) {
            base.copy(frame = storedFrame(item.frame), z = (item.z * 100f).toInt() / 100f)
        } else {
            base.copy(frame = MavFrames.GLOBAL, x = 0, y = 0, z = 0f)
        }
    }

    /** [items] as ArduPilot keeps them (item 0 of a mission excepted, which becomes home). */
    public fun stored(items: List<MissionItem>, fixedWing: Boolean): List<MissionItem> = items.map { stored(it, fixedWing) }

    /**
     * ArduPilot's refusal of [item], or null when it stores it: a NaN where the command does not
     * allow one (`sanity_check_params`), or a location in a frame it does not know.
     */
    public fun problem(item: MissionItem): MissionResult? {
        if (item.missionType != MissionType.MISSION) return null
        val nanAllowed = when (item.command) {
            NAV_WAYPOINT, NAV_LAND, NAV_TAKEOFF, NAV_VTOL_TAKEOFF -> setOf(4)
            NAV_VTOL_LAND -> setOf(3, 4)
            else -> emptySet()
        }
        val params = listOf(item.param1, item.param2, item.param3, item.param4)
        params.forEachIndexed { i, value ->
            if (value.isInfinite() || (value.isNaN() && (i + 1) !in nanAllowed)) return PARAM_RESULTS[i]
        }
        if (item.command in LOCATION_COMMANDS && item.frame !in ACCEPTED_FRAMES) return MissionResult.UNSUPPORTED_FRAME
        return null
    }

    /** param1..param4 as `mission_cmd_to_mavlink_int` rebuilds them, or null for an unknown command. */
    private fun params(item: MissionItem, fixedWing: Boolean): FloatArray? {
        val p1 = item.param1
        val p2 = item.param2
        val p3 = item.param3
        val p4 = item.param4
        fun xtrack() = if (p4 > 0) 1f else 0f
        fun signed(magnitude: Float, ccw: Boolean) = if (ccw) -magnitude else magnitude
        return when (item.command) {
            // Copter keeps the delay in p1; Plane the acceptance radius and pass-by distance, a byte each.
            NAV_WAYPOINT -> if (fixedWing) {
                floatArrayOf(0f, minOf(u16(p2), 255).toFloat(), minOf(u16(p3), 255).toFloat(), 0f)
            } else {
                floatArrayOf(u16(p1).toFloat(), 0f, 0f, 0f)
            }
            NAV_LOITER_UNLIM -> floatArrayOf(0f, 0f, signed(u16(abs(p3)).toFloat(), p3 < 0), 0f)
            // Turns (at most 255) in the low byte of p1, the radius in the high byte: above 255 m in
            // tens of metres (a flag bit says so), so it comes back a multiple of 10.
            NAV_LOITER_TURNS -> {
                val radius = abs(p3)
                val kept = if (radius <= 255f) u8(radius).toFloat() else minOf(255, (radius * 0.1f).toInt()) * 10f
                floatArrayOf(minOf(255, u16(p1)).toFloat(), 0f, signed(kept, p3 < 0), xtrack())
            }
            // The time takes all 16 bits of p1: no room for the radius, only its sign (direction).
            NAV_LOITER_TIME -> floatArrayOf(u16(p1).toFloat(), 0f, if (p3 < 0) -1f else 1f, xtrack())
            NAV_RETURN_TO_LAUNCH, DO_LAND_START, DO_GO_AROUND, NAV_VTOL_TAKEOFF -> floatArrayOf(0f, 0f, 0f, 0f)
            // Only the sign of param4 is kept (deepstall direction), a NaN counting as positive.
            NAV_LAND -> floatArrayOf(u16(p1).toFloat(), 0f, 0f, if (p4 < 0) -1f else 1f)
            NAV_TAKEOFF, NAV_CONTINUE_AND_CHANGE_ALT, NAV_SPLINE_WAYPOINT, NAV_GUIDED_ENABLE, DO_SET_HOME, DO_SET_ROI, NAV_VTOL_LAND,
            DO_FENCE_ENABLE, DO_PARACHUTE, DO_INVERTED_FLIGHT, DO_AUTOTUNE_ENABLE, DO_SET_REVERSE, DO_SET_RESUME_REPEAT_DIST,
            -> floatArrayOf(u16(p1).toFloat(), 0f, 0f, 0f)
            NAV_LOITER_TO_ALT -> floatArrayOf(0f, signed(u16(abs(p2)).toFloat(), p2 < 0), 0f, xtrack())
            NAV_DELAY -> floatArrayOf(p1, i8(p2).toFloat(), i8(p3).toFloat(), i8(p4).toFloat())
            CONDITION_DELAY, CONDITION_DISTANCE -> floatArrayOf(p1, 0f, 0f, 0f)
            DO_SET_CAM_TRIGG_DIST -> floatArrayOf(p1, 0f, u8(p3).toFloat(), 0f)
            CONDITION_YAW -> floatArrayOf(p1, p2, i8(p3).toFloat(), u8(p4).toFloat())
            DO_JUMP -> floatArrayOf(u16(p1).toFloat(), i16(p2).toFloat(), 0f, 0f)
            DO_CHANGE_SPEED -> floatArrayOf(u8(p1).toFloat(), p2, p3, 0f)
            DO_SET_RELAY, DO_GRIPPER -> floatArrayOf(u8(p1).toFloat(), u8(p2).toFloat(), 0f, 0f)
            DO_REPEAT_RELAY -> floatArrayOf(u8(p1).toFloat(), i16(p2).toFloat(), p3, 0f)
            DO_SET_SERVO -> floatArrayOf(u16(p1).toFloat(), u16(p2).toFloat(), 0f, 0f)
            DO_REPEAT_SERVO -> floatArrayOf(u16(p1).toFloat(), u16(p2).toFloat(), i16(p3).toFloat(), p4)
            DO_MOUNT_CONTROL -> floatArrayOf(p1, p2, p3, 0f)
            DO_GUIDED_LIMITS -> floatArrayOf(u16(p1).toFloat(), p2, p3, p4)
            // Kept in centimetres in p1.
            NAV_PAYLOAD_PLACE -> floatArrayOf(u16(p1 * 100) / 100f, 0f, 0f, 0f)
            else -> null
        }
    }

    /** `relative_alt` / `terrain_alt` flags of the stored location, as frames again. */
    private fun storedFrame(frame: Int): Int = when (frame) {
        MavFrames.GLOBAL_RELATIVE_ALT, MavFrames.GLOBAL_RELATIVE_ALT_INT -> MavFrames.GLOBAL_RELATIVE_ALT
        MavFrames.GLOBAL_TERRAIN_ALT, MavFrames.GLOBAL_TERRAIN_ALT_INT -> MavFrames.GLOBAL_TERRAIN_ALT
        else -> MavFrames.GLOBAL // MISSION, GLOBAL, GLOBAL_INT: absolute
    }

    // C's float-to-integer conversion truncates toward zero (undefined out of range: clamped here).
    private fun u16(f: Float) = f.toInt().coerceIn(0, 0xFFFF)
    private fun u8(f: Float) = f.toInt().coerceIn(0, 0xFF)
    private fun i8(f: Float) = f.toInt().coerceIn(-128, 127)
    private fun i16(f: Float) = f.toInt().coerceIn(-32768, 32767)

    private val PARAM_RESULTS = listOf(MissionResult.INVALID_PARAM1, MissionResult.INVALID_PARAM2, MissionResult.INVALID_PARAM3, MissionResult.INVALID_PARAM4)

    /** Frames `mavlink_int_to_mission_cmd` accepts for a location (terrain ones when built with terrain, as SITL is). */
    private val ACCEPTED_FRAMES = setOf(0, 2, 3, 5, 6, 10, 11)

    // The commands AP_Mission stores that MavCommands does not name.
    private const val NAV_GUIDED_ENABLE = 92
    private const val NAV_PAYLOAD_PLACE = 94
    private const val CONDITION_DISTANCE = 114
    private const val DO_SET_RELAY = 181
    private const val DO_REPEAT_RELAY = 182
    private const val DO_REPEAT_SERVO = 184
    private const val DO_GO_AROUND = 191
    private const val DO_SET_ROI = 201
    private const val DO_MOUNT_CONTROL = 205
    private const val DO_FENCE_ENABLE = 207
    private const val DO_PARACHUTE = 208
    private const val DO_INVERTED_FLIGHT = 210
    private const val DO_GRIPPER = 211
    private const val DO_AUTOTUNE_ENABLE = 212
    private const val DO_SET_REVERSE = 194
    private const val DO_SET_RESUME_REPEAT_DIST = 215
    private const val DO_GUIDED_LIMITS = 222

    /** `AP_Mission::stored_in_location`: commands whose x, y, z are a location. */
    private val LOCATION_COMMANDS = setOf(
        NAV_WAYPOINT, NAV_LOITER_UNLIM, NAV_LOITER_TURNS, NAV_LOITER_TIME, NAV_LAND, NAV_TAKEOFF, NAV_CONTINUE_AND_CHANGE_ALT,
        NAV_LOITER_TO_ALT, NAV_SPLINE_WAYPOINT, NAV_GUIDED_ENABLE, DO_SET_HOME, DO_LAND_START, DO_GO_AROUND, DO_SET_ROI,
        NAV_VTOL_TAKEOFF, NAV_VTOL_LAND, NAV_PAYLOAD_PLACE,
    )
}
