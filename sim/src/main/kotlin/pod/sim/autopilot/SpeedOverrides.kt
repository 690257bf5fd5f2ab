package pod.sim.autopilot

/**
 * Speeds a DO_CHANGE_SPEED set (m/s), which win over the parameters' until the vehicle reboots;
 * null: the parameter's value.
 */
internal class SpeedOverrides {
    /** Cruise (air or ground) speed. */
    var cruise: Double? = null
        private set

    /** Climb rate. */
    var climb: Double? = null
        private set

    /** Descent rate. */
    var descent: Double? = null
        private set

    /**
     * DO_CHANGE_SPEED: [kind] 0 air / 1 ground / 2 climb / 3 descent, [speed] m/s (-1 or less:
     * unchanged). False for an unknown kind.
     */
    fun change(kind: Int, speed: Double): Boolean {
        if (speed <= 0) return true
        when (kind) {
            0, 1 -> cruise = speed
            2 -> climb = speed
            3 -> descent = speed
            else -> return false
        }
        return true
    }
}
