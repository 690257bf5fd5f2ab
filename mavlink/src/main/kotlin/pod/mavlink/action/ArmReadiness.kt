package pod.mavlink.action

/**
 * Whether an autopilot's refusal to arm can clear by waiting: a vehicle still initialising
 * (estimator without an origin, no home, GPS without a fix, sensors settling) is ready in tens of
 * seconds; a flat battery or a mode that cannot be armed never is.
 *
 * Judged from the lines the autopilot sent with the refusal, as ArduPilot 4.7 and PX4 word them:
 * any line that names a lasting problem fails at once; otherwise a line that names initialising
 * means wait. A refusal without a line (the text was lost) is waited on only while the vehicle's
 * own state says it is initialising ([initialising]).
 */
internal object ArmReadiness {
    /**
     * Lines that clear once the vehicle has booted. ArduPilot: AP_Arming::ins_checks ("Accels
     * inconsistent", "Gyros inconsistent" while SITL's IMUs settle), AP_Arming::gps_checks and
     * AP_AHRS ("AHRS: waiting for home", "Need 3D Fix", "Need Position Estimate", EKF
     * "waiting for GPS"/"still initialising"); PX4's commander ("no valid global position estimate").
     */
    private val INITIALISING = listOf(
        "inconsistent", "waiting for home", "waiting for", "need 3d fix", "need position estimate", "position estimate",
        "ekf", "ahrs", "initialising", "initializing", "gps", "calibration in progress", "not ready",
    )

    /**
     * Lines that waiting will not clear: the battery (AP_Arming::battery_checks, PX4 "low battery"),
     * the mode (AP_Arming_Copter::mandatory_checks "Mode not armable", ArduPlane "RTL mode not
     * armable"), the mission (ArduPlane "DO_LAND_START set and RTL_AUTOLAND disabled"), the pilot's
     * controls, the fence.
     */
    private val LASTING = listOf(
        "battery", "voltage", "not armable", "do_land_start", "rtl_autoland", "throttle", "safety switch",
        "fence", "interlock", "emergency stop", "rc not", "radio", "disarm switch",
    )

    /**
     * Mode changes refused until the estimator has a position: ArduCopter's Copter::set_mode
     * ("Mode change to GUIDED failed: requires position", "need alt estimate", ArduCopter/mode.cpp);
     * PX4's commander while a mode's requirements are not met yet ("Switching to Hold is currently
     * not available", ModeUtil/mode_requirements.cpp), which waiting clears only while initialising.
     */
    private val MODE_INITIALISING = listOf("requires position", "need alt estimate", "need position")

    /** The reason to wait for a refused mode change, or null when waiting will not clear it. */
    fun modeWaitFor(lines: List<String>, initialising: Boolean): String? {
        val lower = lines.map { it.lowercase() }
        val waiting = lines.filterIndexed { i, _ -> MODE_INITIALISING.any { it in lower[i] } || (initialising && "currently not available" in lower[i]) }
        return waiting.takeIf { it.isNotEmpty() }?.joinToString("; ")
    }

    /** The reason to wait for, or null when [lines] say the refusal will not clear by waiting. */
    fun waitFor(lines: List<String>, initialising: Boolean): String? {
        val lower = lines.map { it.lowercase() }
        if (lower.any { line -> LASTING.any { it in line } }) return null
        val waiting = lines.filterIndexed { i, _ -> INITIALISING.any { it in lower[i] } }
        return when {
            waiting.isNotEmpty() -> waiting.joinToString("; ")
            lines.isEmpty() && initialising -> "the vehicle to finish initialising"
            else -> null
        }
    }
}
