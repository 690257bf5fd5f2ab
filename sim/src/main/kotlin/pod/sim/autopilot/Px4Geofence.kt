package pod.sim.autopilot

import pod.core.units.Location
import pod.core.vehicle.Severity
import pod.sim.flight.horizontalDistance

/**
 * PX4's geofence, after src/modules/navigator/geofence.cpp and Navigator::geofence_breach_check
 * (navigator_main.cpp, every 200 ms) and the commander's failsafe framework
 * (src/modules/commander/failsafe/failsafe.cpp Failsafe::fromGfActParam, framework.cpp).
 *
 * The position breaches when it is GF_MAX_HOR_DIST or more from home, GF_MAX_VER_DIST or more
 * above it (both 0 = off, the defaults), or outside any inclusion zone or inside any exclusion
 * zone (Geofence::isInsidePolygonOrCircle: every zone must pass). Nothing is checked while
 * GF_ACTION is 0. The failsafe starts on the rising edge of the breach while armed
 * (FailsafeBase::checkFailsafe; arming and disarming clear it): GF_ACTION 1 only warns, 2 (the
 * default) holds (AUTO.LOITER, where it is: GF_PREDICT is 0), 3 returns, 4 terminates (the sim
 * disarms), 5 lands. Return and Land come after COM_FAIL_ACT_T seconds of Hold (their takeover
 * is Auto, so the delay applies; Hold's is AlwaysModeSwitchOnly). A mode change by the ground
 * station takes over; the next breach acts again. STATUSTEXT as FailsafeBase::notifyUser sends it
 * (CRITICAL; the real line ends with a tab, which the sim drops as for its other PX4 lines).
 *
 * Not modelled: GF_PREDICT, the mission feasibility check against the fence, PX4's refusal to arm
 * outside the fence.
 */
internal class Px4Geofence(ap: FlightControl) : Geofence(ap) {
    private var breached = false
    private var wasArmed = false
    private var delayed: Pair<String, Double>? = null

    private val action: Int get() = ap.params["GF_ACTION"].toInt()

    override val checkInterval: Double = 0.2 // GEOFENCE_CHECK_INTERVAL_US

    override fun step() {
        super.step()
        val (mode, at) = delayed ?: return
        if (ap.time < at) return
        delayed = null
        ap.text(Severity.CRITICAL, "Failsafe activated")
        setModeByFence(mode)
    }

    override fun modeChanged() {
        super.modeChanged()
        delayed = null // a mode switch during the delayed Hold takes over (FailsafeBase::getSelectedAction)
    }

    override fun check() {
        if (ap.armed != wasArmed) {
            wasArmed = ap.armed
            breached = false
            delayed = null
        }
        if (action == NONE) return
        val now = !inside(ap.body.location)
        val rising = now && !breached
        breached = now
        if (!rising || !ap.armed) return
        when (action) {
            WARN -> ap.text(Severity.CRITICAL, "Failsafe activated")
            HOLD -> {
                ap.text(Severity.CRITICAL, "Failsafe activated")
                setModeByFence("AUTO.LOITER")
            }
            RETURN, LAND -> {
                val mode = if (action == RETURN) "AUTO.RTL" else "AUTO.LAND"
                val delay = ap.params["COM_FAIL_ACT_T"]
                if (delay > 0.1) {
                    ap.text(Severity.CRITICAL, "Failsafe activated, entering Hold for ${(delay + 0.5).toInt()} seconds")
                    setModeByFence("AUTO.LOITER")
                    delayed = mode to ap.time + delay
                } else {
                    ap.text(Severity.CRITICAL, "Failsafe activated")
                    setModeByFence(mode)
                }
            }
            TERMINATE -> {
                ap.text(Severity.CRITICAL, "Failsafe activated")
                ap.disarm()
            }
        }
    }

    private fun inside(at: Location): Boolean {
        val maxHorizontal = ap.params["GF_MAX_HOR_DIST"]
        if (maxHorizontal > 0 && horizontalDistance(ap.home, at) >= maxHorizontal) return false
        val maxVertical = ap.params["GF_MAX_VER_DIST"]
        if (maxVertical > 0 && heightAboveHome(at) >= maxVertical) return false
        return zones.violated(at).isEmpty()
    }

    /**
     * Geofence::_updateFence drops each zone that does not contain home, and, when flying with
     * GF_ACTION set, each zone that does not contain the vehicle, saying why
     * (checkHomeRequirementsForGeofence, checkCurrentPositionRequirementsForGeofence).
     */
    override fun accept(loaded: FenceZones): FenceZones = loaded.filter { zone ->
        val homeOk = !ap.positionReady || zone.contains(ap.home) == zone.inclusion
        if (!homeOk) ap.text(Severity.CRITICAL, "Geofence invalid, doesn't contain Home position")
        val hereOk = action == NONE || !ap.flying || zone.contains(ap.body.location) == zone.inclusion
        if (!hereOk) ap.text(Severity.CRITICAL, "Geofence invalid, doesn't contain current vehicle position")
        homeOk && hereOk
    }

    /**
     * Navigator::geofence_allows_position, for every GF_ACTION but None and Warning: a DO_REPOSITION
     * outside is acknowledged by the commander but not flown ("Reposition is outside geofence").
     */
    override fun allowsDestination(target: Location): Boolean {
        refresh()
        return action == NONE || action == WARN || inside(target)
    }

    private companion object {
        const val NONE = 0
        const val WARN = 1
        const val HOLD = 2
        const val RETURN = 3
        const val TERMINATE = 4
        const val LAND = 5
    }
}
