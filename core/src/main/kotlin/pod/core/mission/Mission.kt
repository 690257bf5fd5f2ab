package pod.core.mission

import pod.core.units.Location

/**
 * A mission: a named, ordered list of [steps] that one vehicle flies, independent of any protocol.
 *
 * Every [Location] in [steps] carries its altitude as a height above the vehicle's home (where it
 * took off), not above mean sea level; the MAVLink module sends them in the relative-altitude frame.
 * [home] is where the mission was planned from (relative moves start there); its altitude, when
 * known, is above mean sea level. The vehicle keeps its own home: a mission does not move it.
 * Build one with the `mission { }` builder of pod-dsl, which checks every argument.
 */
public data class Mission(
    /** A name for people and logs. */
    public val name: String,
    /** The launch point the mission was planned from (altitude above sea level, 0 if unknown), or null. */
    public val home: Location?,
    /** The steps in flying order. */
    public val steps: List<MissionStep>,
) {
    /** How the mission ends, which decides when a vehicle flying it counts as done. */
    public val completion: MissionCompletion
        get() = when (val last = steps.lastOrNull { it !is MissionStep.Action }) {
            is MissionStep.Land, MissionStep.ReturnHome -> MissionCompletion.LANDED
            is MissionStep.Loiter -> if (last.duration == LoiterDuration.Unlimited) MissionCompletion.LOITERING else MissionCompletion.LAST_STEP_DONE
            else -> MissionCompletion.LAST_STEP_DONE
        }
}

/**
 * When a vehicle flying a mission counts as done (the original Dolphin plugin waited for 5 s in
 * RTL, so missions ending in a loiter or a landing never completed).
 */
public enum class MissionCompletion {
    /** The last step was reached and finished; the vehicle then holds where it is. */
    LAST_STEP_DONE,

    /** The mission ends with a landing (a landing point or return home): done once landed and disarmed. */
    LANDED,

    /**
     * The mission ends in an unlimited loiter: it is never done by itself. The vehicle circles
     * there until the task is cancelled (Dolphin's `moveAndLoiterPos … until { battery(v) < 0.3 }`);
     * being established on the circle is reported ([pod.core.platform.MissionEvent.Loitering]) and
     * can be waited for (`waitFor { loitering(v) }`).
     */
    LOITERING,
}
