package pod.mavlink.command

import pod.core.mission.SpeedKind

/**
 * MAV_CMD_DO_CHANGE_SPEED's param1 ("speed type": 0 airspeed, 1 ground speed, 2 climb, 3 descent)
 * for each [SpeedKind], both ways: what Pod sends in missions and commands and reads back from
 * mission files.
 */
internal object SpeedTypes {
    /** The speed type on the wire for [kind]. */
    fun of(kind: SpeedKind): Int = when (kind) {
        SpeedKind.AIR -> 0
        SpeedKind.GROUND -> 1
        SpeedKind.CLIMB -> 2
        SpeedKind.DESCENT -> 3
    }

    /** The kind a speed type on the wire means; an unknown number is taken as ground speed, the default. */
    fun kindOf(speedType: Int): SpeedKind = when (speedType) {
        0 -> SpeedKind.AIR
        2 -> SpeedKind.CLIMB
        3 -> SpeedKind.DESCENT
        else -> SpeedKind.GROUND
    }
}
