package pod.sim.autopilot

import pod.core.units.Location
import pod.core.units.m
import pod.core.vehicle.Severity
import pod.mavlink.command.CommandResult
import pod.sim.flight.horizontalDistance

/**
 * ArduCopter's and ArduPlane's fence (4.7), after libraries/AC_Fence/AC_Fence.cpp and
 * AC_PolyFence_loader.cpp, ArduCopter/fence.cpp and ArduPlane/fence.cpp.
 *
 * FENCE_ENABLE (default 0) switches on the FENCE_TYPE bits (Copter 7: max altitude, circle around
 * home, uploaded polygons and circles; Plane 4: uploaded zones only), as does DO_FENCE_ENABLE
 * without touching the parameter. AC_Fence::check reports only fresh breaches, so the action runs
 * once, and again only after the breach cleared, or, for the max-altitude and home-circle fences,
 * once the vehicle is 20 m (Plane's circle: 100 m) past where it breached (the backup fences). Any
 * mode change while breached starts 10 s of "manual recovery" in which nothing is reported
 * (AC_Fence::manual_recovery_start from Copter::set_mode and Plane's Mode::enter). The fence is
 * checked armed or not (a breach on the ground blocks arming) and acted on only when armed.
 *
 * Not modelled: the minimum-altitude fence and FENCE_AUTOENABLE, margin notifications, Copter's
 * AC_Avoid pushing back at the fence (pilot modes only), rally points as return points, Plane's
 * landing exceptions (no breach in the flare; none while landing with RTL_AUTOLAND).
 */
internal class ArduPilotFence(ap: FlightControl, private val copter: Boolean) : Geofence(ap) {
    private var lastEnableParam = Double.NaN
    private var enabledTypes = 0

    /** The fence types breached now (AC_Fence's _breached_fences). */
    private var breaches = 0
    private var breachCount = 0
    private var breachTimeMs = 0L
    private var lastStatusAt = Double.NEGATIVE_INFINITY
    private var altBackup = 0.0
    private var circleBackup = 0.0
    private var altDistance = 0.0
    private var circleDistance = 0.0
    private var polygonDistance = 0.0
    private var recoveryUntil = Double.NEGATIVE_INFINITY

    private val action: Int get() = ap.params["FENCE_ACTION"].toInt()

    // Copter::fence_checks_async runs at 25 Hz, Plane::fence_checks_async at 3 Hz.
    override val checkInterval: Double = if (copter) 0.04 else 0.333

    override fun modeChanged() {
        super.modeChanged()
        // Copter calls manual_recovery_start unless FENCE_ACTION is report-only; Plane always.
        if (breaches != 0 && (!copter || action != REPORT_ONLY)) recoveryUntil = ap.time + MANUAL_RECOVERY_SECONDS
    }

    override fun refresh() {
        super.refresh()
        // AC_Fence::update: a change of FENCE_ENABLE enables every configured fence but the floor, or none.
        val enable = ap.params["FENCE_ENABLE"]
        if (enable != lastEnableParam) {
            lastEnableParam = enable
            enabledTypes = if (enable != 0.0) configured() and ALT_MIN.inv() else 0
        }
    }

    private fun configured(): Int = ap.params["FENCE_TYPE"].toInt()

    /** AC_Fence::present: the configured types, polygons only once a fence is loaded. */
    private fun present(): Int = configured() and (ALT_MAX or CIRCLE or ALT_MIN or if (zones.isEmpty) 0 else POLYGON)

    private fun enabled(): Int = enabledTypes and present()

    /**
     * AC_PolyFence_loader::breached: inside any exclusion zone, or outside an inclusion zone (all
     * of them with FENCE_OPTIONS bit 1, the union of inclusion areas). The zones breached, or none.
     */
    private fun polygonBreach(at: Location): List<FenceZones.Zone> {
        val violated = zones.violated(at)
        if (violated.any { !it.inclusion }) return violated
        val inclusions = zones.zones.count { it.inclusion }
        val outside = violated.count { it.inclusion }
        val union = ap.params["FENCE_OPTIONS"].toInt() and OPTION_INCLUSION_UNION != 0
        return if ((union && inclusions > 0 && outside == inclusions) || (!union && outside > 0)) violated else emptyList()
    }

    /** AC_Fence::check: the fence types freshly breached (none during manual recovery). */
    private fun freshBreaches(): Int {
        val enabled = enabled()
        // A disabled fence has no breach (AC_Fence::enable(false) and check_fence_polygon clear it).
        breaches = breaches and enabled
        if (enabled == 0) return 0
        val here = ap.body.location
        var fresh = 0
        if (enabled and ALT_MAX != 0) {
            val height = heightAboveHome(here)
            altDistance = height - ap.params["FENCE_ALT_MAX"]
            if (altDistance >= 0) {
                if (breaches and ALT_MAX == 0 || (altBackup != 0.0 && height >= altBackup)) {
                    fresh = fresh or record(ALT_MAX)
                    altBackup = height + ALT_BACKUP_METRES
                }
            } else {
                breaches = breaches and ALT_MAX.inv()
                altBackup = 0.0
            }
        }
        if (enabled and CIRCLE != 0) {
            val fromHome = horizontalDistance(ap.home, here)
            circleDistance = fromHome - ap.params["FENCE_RADIUS"]
            if (circleDistance >= 0) {
                if (breaches and CIRCLE == 0 || (circleBackup != 0.0 && fromHome >= circleBackup)) {
                    fresh = fresh or record(CIRCLE)
                    circleBackup = fromHome + if (copter) COPTER_CIRCLE_BACKUP_METRES else PLANE_CIRCLE_BACKUP_METRES
                }
            } else {
                breaches = breaches and CIRCLE.inv()
                circleBackup = 0.0
            }
        }
        if (enabled and POLYGON != 0) {
            val breached = polygonBreach(here)
            polygonDistance = breached.maxOfOrNull { it.distanceToEdge(here) } ?: 0.0
            if (breached.isEmpty()) breaches = breaches and POLYGON.inv() else if (breaches and POLYGON == 0) fresh = fresh or record(POLYGON)
        }
        return if (ap.time < recoveryUntil) 0 else fresh
    }

    /**
     * AC_Fence::record_breach; the first breach also sends FENCE_STATUS, at most once a second
     * (GCS_SEND_MESSAGE(MSG_FENCE_STATUS); GCS_MAVLINK::send_fence_status in GCS_Fence.cpp fills it).
     */
    private fun record(type: Int): Int {
        val first = breaches == 0
        breachCount = minOf(breachCount + 1, 65500)
        breaches = breaches or type
        if (first) {
            breachTimeMs = (ap.time * 1000).toLong()
            if (ap.time - lastStatusAt > 1.0) {
                lastStatusAt = ap.time
                val boundary = breaches and (CIRCLE or POLYGON) != 0
                // Copter's AC_Avoid is not limiting in the modes a station flies (MITIGATE_NONE); Plane has none (UNKNOWN).
                ap.emit(SimOutput.FenceStatus(true, breachCount, if (boundary) BREACH_BOUNDARY else BREACH_MAXALT, breachTimeMs, if (copter) 1 else 0))
            }
        }
        return type
    }

    /** AC_Fence::get_breach_distance over [types]. */
    private fun breachDistance(types: Int): Double = listOfNotNull(
        altDistance.takeIf { types and ALT_MAX != 0 },
        circleDistance.takeIf { types and CIRCLE != 0 },
        polygonDistance.takeIf { types and POLYGON != 0 },
    ).maxOrNull() ?: 0.0

    override fun check() = if (copter) copterCheck() else planeCheck()

    /**
     * Copter::fence_checks_async and Copter::fence_check. "Fence breach cleared" and "… breached"
     * (NOTICE) only in the air. On the ground, or in a manual-throttle mode with the throttle at zero
     * (the simulator's sticks) and no altitude breach, it disarms; more than 100 m outside
     * (AC_FENCE_GIVE_UP_DISTANCE) it lands; else FENCE_ACTION: 1 RTL (the default), 2 LAND, 3 and
     * 5 SMART_RTL, 4 BRAKE. The sim's modes cannot refuse, so the "or LAND" fallbacks never run.
     */
    private fun copterCheck() {
        val before = breaches
        val fresh = freshBreaches()
        if (fresh == 0 && before != 0 && breaches == 0 && ap.flying) ap.text(Severity.NOTICE, "Fence breach cleared")
        if (!ap.armed || fresh == 0) return
        if (ap.flying) ap.text(Severity.NOTICE, "${names(fresh)} breached")
        if (action == REPORT_ONLY) return
        val manualThrottle = ap.profile.behaviour(ap.modeName) == Behaviour.MANUAL
        if (!ap.flying || (manualThrottle && breaches and ALT_MAX == 0)) {
            ap.disarm()
            return
        }
        setModeByFence(
            when {
                breachDistance(fresh) > GIVE_UP_METRES || action == 2 -> "LAND"
                action == 3 || action == 5 -> "SMART_RTL"
                action == 4 -> "BRAKE"
                else -> "RTL"
            },
        )
    }

    /**
     * Plane::fence_check. A disabled fence gives a plane it put in GUIDED its previous mode back.
     * While the mode is the fence's (Plane::in_fence_recovery) nothing triggers again, and the
     * breach is not announced as cleared. FENCE_ACTION 1 (default) and 8: RTL (the sim has no
     * AUTOLAND mode); 6 and 7: GUIDED to the fence return point, else the first inclusion polygon's
     * centre, else home, at FENCE_RET_ALT above home, else half way between the altitude fences'
     * safe limits; Copter-only actions do nothing.
     */
    private fun planeCheck() {
        val before = breaches
        val fresh = freshBreaches()
        if (enabled() == 0) {
            if (modeByFence && ap.modeName == "GUIDED" && action in setOf(1, 6, 7, 8)) modeBeforeFence?.let { ap.setMode(it) }
            forgetFenceMode()
            return
        }
        if (!ap.armed || modeByFence) return
        if (fresh != 0) {
            ap.text(Severity.NOTICE, "${names(fresh)} breached")
            when (action) {
                1, 8 -> setModeByFence("RTL")
                6, 7 -> {
                    setModeByFence("GUIDED")
                    val (radius, clockwise) = ap.loiterRadius()
                    ap.fly(Activity.GoTo(planeReturnPoint(), null, radius, clockwise, from = ap.body.location))
                }
            }
        } else if (before != 0 && breaches == 0) {
            ap.text(Severity.NOTICE, "Fence breach cleared")
        }
    }

    private fun planeReturnPoint(): Location {
        val safeMin = ap.params["FENCE_ALT_MIN"] + ap.params["FENCE_MARGIN"]
        val safeMax = ap.params["FENCE_ALT_MAX"] - ap.params["FENCE_MARGIN"]
        val height = when {
            ap.params["FENCE_RET_ALT"] > 0 -> ap.params["FENCE_RET_ALT"]
            safeMin >= safeMax -> ap.params["ALT_HOLD_RTL"] / 100
            else -> (safeMin + safeMax) / 2
        }
        val point = zones.returnPoint ?: zones.centroidOfFirstInclusion()
        return Location(point?.latitude ?: ap.home.latitude, point?.longitude ?: ap.home.longitude, (ap.home.altitude.meters + height).m)
    }

    /**
     * GCS_MAVLINK::handle_command_do_fence_enable (GCS_Fence.cpp): param1 0 disables, 1 enables
     * (FAILED when none of the fences asked for is present), 2 disables the floor; param2 the
     * FENCE_TYPE bits (0: all).
     */
    override fun enableCommand(cmd: CommandRequest): CommandResult {
        refresh()
        val types = (cmd.param2.toInt() and 0xFF).takeIf { it != 0 } ?: ALL
        return when (cmd.param1.toInt()) {
            0 -> CommandResult.ACCEPTED.also { enable(false, types) }
            1 -> if (present() and types == 0) CommandResult.FAILED else CommandResult.ACCEPTED.also { enable(true, types) }
            2 -> CommandResult.ACCEPTED.also { enable(false, ALT_MIN) }
            else -> CommandResult.FAILED
        }
    }

    /** AC_Fence::enable(value, fence_types): only configured types change; disabling clears their breaches. */
    private fun enable(value: Boolean, types: Int) {
        val fences = configured() and types
        val next = if (value) enabledTypes or fences else enabledTypes and fences.inv()
        if (!value) breaches = breaches and (enabledTypes xor next).inv()
        enabledTypes = next
    }

    /**
     * AC_Fence::check_destination_within_fence over the enabled fences: ArduCopter's
     * ModeGuided::set_destination refuses a target outside (DO_REPOSITION FAILED),
     * GCS_MAVLINK_Plane::handle_command_int_do_reposition too (DENIED).
     */
    override fun allowsDestination(target: Location): Boolean {
        refresh()
        val enabled = enabled()
        val tooHigh = enabled and ALT_MAX != 0 && heightAboveHome(target) > ap.params["FENCE_ALT_MAX"]
        val tooFar = enabled and CIRCLE != 0 && horizontalDistance(ap.home, target) > ap.params["FENCE_RADIUS"]
        return !tooHigh && !tooFar && (enabled and POLYGON == 0 || polygonBreach(target).isEmpty())
    }

    /** AC_Fence::pre_arm_check as AP_Arming::fence_checks reports it: no fence present, or one breached now. */
    override fun armingProblem(): String? {
        refresh()
        if (ap.params["FENCE_ENABLE"] != 0.0 && present() == 0) return "Fences enabled, but none selected"
        return if (enabled() != 0 && breaches != 0) "Vehicle breaching ${names(breaches)}" else null
    }

    /**
     * FENCE_OPTIONS bit 0 (Plane's default) refuses mode changes while recovering from a breach.
     * Copter::set_mode (ArduCopter/mode.cpp): "Mode change to X failed: in fence recovery" (WARNING,
     * mode_change_failed), only in the air; Plane::set_mode (ArduPlane/system.cpp): "Mode change to
     * X denied, in fence recovery" (NOTICE).
     */
    override fun refusesModeChange(name: String): Pair<String, Severity>? {
        refresh()
        val option = ap.params["FENCE_OPTIONS"].toInt() and OPTION_DISABLE_MODE_CHANGE != 0
        if (!option || !ap.armed || enabled() == 0 || breaches == 0 || !modeByFence) return null
        return when {
            !copter -> "Mode change to $name denied, in fence recovery" to Severity.NOTICE
            ap.flying -> "Mode change to $name failed: in fence recovery" to Severity.WARNING
            else -> null
        }
    }

    /** [fences] named as AC_Fence::get_fence_names does: "Polygon fence", "Max Alt and Polygon fences". */
    private fun names(fences: Int): String {
        val names = FENCE_NAMES.filterIndexed { i, _ -> fences and (1 shl i) != 0 }
        val joined = if (names.size == 1) names[0] else names.dropLast(1).joinToString(", ") + " and " + names.last()
        return joined + if (names.size > 1) " fences" else " fence"
    }

    companion object {
        /** FENCE_TYPE bits. */
        const val ALT_MAX = 1
        const val CIRCLE = 2
        const val POLYGON = 4
        const val ALT_MIN = 8
        private const val ALL = ALT_MAX or CIRCLE or POLYGON or ALT_MIN
        private val FENCE_NAMES = listOf("Max Alt", "Circle", "Polygon", "Min Alt")

        private const val REPORT_ONLY = 0
        private const val OPTION_DISABLE_MODE_CHANGE = 1
        private const val OPTION_INCLUSION_UNION = 2
        private const val MANUAL_RECOVERY_SECONDS = 10.0 // AC_FENCE_MANUAL_RECOVERY_TIME_MIN
        private const val ALT_BACKUP_METRES = 20.0 // AC_FENCE_ALT_MAX_BACKUP_DISTANCE
        private const val COPTER_CIRCLE_BACKUP_METRES = 20.0 // AC_FENCE_CIRCLE_RADIUS_BACKUP_DISTANCE
        private const val PLANE_CIRCLE_BACKUP_METRES = 100.0 // the same, ArduPlane
        private const val GIVE_UP_METRES = 100.0 // AC_FENCE_GIVE_UP_DISTANCE
        private const val BREACH_MAXALT = 2 // FENCE_BREACH_MAXALT
        private const val BREACH_BOUNDARY = 3 // FENCE_BREACH_BOUNDARY
    }
}
