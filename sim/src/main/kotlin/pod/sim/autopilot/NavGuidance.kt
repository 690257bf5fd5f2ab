package pod.sim.autopilot

import pod.core.units.Location
import pod.core.vehicle.Severity
import pod.mavlink.command.MavCommands.NAV_CONTINUE_AND_CHANGE_ALT
import pod.mavlink.command.MavCommands.NAV_DELAY
import pod.mavlink.command.MavCommands.NAV_LAND
import pod.mavlink.command.MavCommands.NAV_LOITER_TIME
import pod.mavlink.command.MavCommands.NAV_LOITER_TURNS
import pod.mavlink.command.MavCommands.NAV_LOITER_UNLIM
import pod.mavlink.command.MavCommands.NAV_RETURN_TO_LAUNCH
import pod.mavlink.command.MavCommands.NAV_TAKEOFF
import pod.mavlink.command.MavCommands.NAV_VTOL_LAND
import pod.mavlink.command.MavCommands.NAV_VTOL_TAKEOFF
import pod.mavlink.mission.MissionItem
import pod.sim.flight.Guidance
import pod.sim.flight.horizontalDistance
import pod.sim.flight.northEast
import kotlin.math.abs
import kotlin.math.atan2

/** How far the NAV item being flown has got; a new item starts a new one. */
internal class ItemProgress {
    var target: Location? = null
    var arrivedAt: Double? = null
    var circled = 0.0
    var lastBearing: Double? = null
    var waitUntil: Double? = null
    var plan: ReturnPlan? = null
    var approach: SlopeLanding? = null
    var legStart: Location? = null
}

/** What [NavGuidance] sees of the mission being flown, and the two things it may change of it. */
internal interface MissionLeg {
    /** The MISSION list. */
    val items: List<MissionItem>

    /** The index of the item being flown. */
    val seq: Int

    /** The first item AUTO flies. */
    val first: Int

    /** How far the item being flown has got. */
    val progress: ItemProgress

    /** Where the vehicle holds once the item is done (null: where it is). */
    fun holdAt(at: Location?)

    /** Whether the item being flown is a landing now. */
    fun landing(now: Boolean)

    /** Where [item] points, its altitude resolved. */
    fun location(item: MissionItem): Location

    /** Holding where the mission holds. */
    fun hold(): Guidance
}

/**
 * Navigation guidance for one NAV item of a mission: what to fly until it completes. The
 * branches on [pod.sim.autopilot.profile.AutopilotProfile.rotorcraft] are the airframe's
 * (both firmwares fly a multirotor through a waypoint and a plane past its finish line); the
 * firmware's own facts are its profile's.
 */
internal class NavGuidance(private val ap: FlightControl, private val leg: MissionLeg) {
    private val profile get() = ap.profile
    private val item get() = leg.progress

    /** The guidance for NAV item [it], or null when it is complete. */
    fun guidance(it: MissionItem): Guidance? {
        val body = ap.body
        val target = item.target ?: leg.location(it).also { t -> item.target = t }
        if (body.onGround && it.command != NAV_TAKEOFF && it.command != NAV_VTOL_TAKEOFF && it.command != NAV_LAND) {
            // Some firmwares (PX4) take off by themselves before the first item; ArduPilot needs a take-off item.
            if (!profile.autoTakesOffByItself || !ap.armed) return Guidance.Idle
            return Guidance.Climb(maxOf(target.altitude.meters, ap.takeoffAltitude(null)))
        }
        return when (it.command) {
            NAV_TAKEOFF, NAV_VTOL_TAKEOFF -> when {
                !ap.armed -> Guidance.Idle
                ap.takeoffReached(target.altitude.meters) -> null
                else -> Guidance.Climb(target.altitude.meters)
            }
            NAV_LAND, NAV_VTOL_LAND -> {
                leg.landing(true)
                leg.holdAt(null)
                if (profile.landsOnGlideSlope) return slopeLanding(target)
                // Airframe: a multirotor descends where it is, a plane glides to the point.
                Guidance.Land(if (it.x == 0 && it.y == 0) (if (profile.rotorcraft) null else body.location) else target)
            }
            NAV_RETURN_TO_LAUNCH -> {
                val plan = item.plan ?: ap.returnPlan().also { p -> item.plan = p }
                val g = plan.guidance(body)
                leg.landing(plan.landing)
                if (plan.circlingHome) null else g
            }
            NAV_LOITER_UNLIM -> loiter(it, target)
            NAV_DELAY -> {
                val until = item.waitUntil ?: (ap.time + it.param1).also { t -> item.waitUntil = t }
                leg.holdAt(target)
                if (ap.time < until) leg.hold() else null
            }
            NAV_CONTINUE_AND_CHANGE_ALT -> when {
                abs(body.location.altitude.meters - target.altitude.meters) < 2.0 -> null
                profile.rotorcraft -> Guidance.GoTo(target) // airframe: a multirotor climbs in place
                else -> Guidance.Cruise(body.heading, target.altitude.meters)
            }
            NAV_LOITER_TIME -> loiter(it, target).takeIf { _ -> item.arrivedAt.let { a -> a == null || ap.time - a < it.param1 } }
            NAV_LOITER_TURNS -> turns(it, target)
            else -> waypoint(it, target)
        }
    }

    /** ArduPlane's NAV_LAND: the glide slope from the previous waypoint, flown by [SlopeLanding]. */
    private fun slopeLanding(target: Location): Guidance {
        val approach = item.approach ?: SlopeLanding(ap, previousWaypoint() ?: ap.body.location, target).also { a ->
            item.approach = a
            ap.text(Severity.INFO, String.format(java.util.Locale.ROOT, "Landing glide slope %.1f degrees", a.slopeDegrees))
        }
        return approach.guidance()
    }

    /** Where the NAV item before the current one pointed (what ArduPlane calls prev_WP_loc), or null. */
    private fun previousWaypoint(): Location? =
        (leg.seq - 1 downTo leg.first).asSequence().map { leg.items[it] }.firstOrNull { it.command in MissionRunner.NAV && (it.x != 0 || it.y != 0) }?.let { leg.location(it) }

    // Airframe, not firmware: a multirotor arrives at a waypoint's height and may hold there; a plane never stops.
    private fun waypoint(it: MissionItem, target: Location): Guidance? {
        val body = ap.body
        if (item.arrivedAt == null) {
            val d = horizontalDistance(body.location, target)
            val radius = ap.acceptanceRadius(it.param2)
            val arrived = if (profile.rotorcraft) {
                d < radius && abs(body.location.altitude.meters - target.altitude.meters) < 1.0
            } else {
                // A plane also counts a waypoint whose finish line it has crossed: the line through the
                // waypoint square to the leg (ArduPlane verify_nav_wp, Location::past_interval_finish_line).
                d < radius || pastFinishLine(target)
            }
            if (!arrived) return Guidance.GoTo(target, through = if (profile.rotorcraft) ThroughSpeed.of(ap, leg, it, target) else 0.0, throughRadius = radius)
            item.arrivedAt = ap.time
            leg.holdAt(target)
        }
        val holdFor = if (profile.rotorcraft) it.param1.toDouble() else 0.0
        return if (ap.time - item.arrivedAt!! < holdFor) Guidance.Loiter(target, 0.0) else null
    }

    /** Whether the plane is past the line through [target] square to the leg from the previous waypoint. */
    private fun pastFinishLine(target: Location): Boolean {
        val from = item.legStart ?: (previousWaypoint() ?: ap.body.location).also { item.legStart = it }
        val (ln, le) = northEast(from, target)
        val length = kotlin.math.hypot(ln, le)
        if (length < 1.0) return false
        val (n, e) = northEast(from, ap.body.location)
        return (n * ln + e * le) / length >= length
    }

    private fun radiusOf(it: MissionItem): Pair<Double, Boolean> {
        val r = it.param3.toDouble()
        return when {
            it.command == NAV_LOITER_TIME && profile.loiterTimeUsesLoiterRadius -> ap.loiterRadius().let { (radius, cw) -> radius to (if (r != 0.0) r > 0 else cw) }
            r != 0.0 -> abs(r) to (r > 0)
            profile.rotorcraft -> 0.0 to true // airframe: a multirotor loiters on the spot
            else -> ap.loiterRadius()
        }
    }

    private fun loiter(it: MissionItem, target: Location): Guidance {
        val (radius, cw) = radiusOf(it)
        leg.holdAt(target)
        if (item.arrivedAt == null && onCircle(target, radius)) item.arrivedAt = ap.time
        return Guidance.Loiter(target, radius, cw)
    }

    private fun turns(it: MissionItem, target: Location): Guidance? {
        var (radius, cw) = radiusOf(it)
        // Airframe: the simulated multirotor does not pivot on the spot; it flies the circle mode's radius.
        if (profile.rotorcraft && radius == 0.0) radius = profile.circleMode(ap.params).first
        leg.holdAt(target)
        if (onCircle(target, radius)) {
            val (n, e) = northEast(target, ap.body.location)
            val bearing = Math.toDegrees(atan2(e, n))
            item.lastBearing?.let { last ->
                var delta = bearing - last
                if (delta > 180) delta -= 360
                if (delta < -180) delta += 360
                item.circled += if (cw) delta else -delta
            }
            item.lastBearing = bearing
        }
        return if (item.circled >= abs(it.param1) * 360.0) null else Guidance.Loiter(target, radius, cw)
    }

    private fun onCircle(center: Location, radius: Double): Boolean {
        val d = horizontalDistance(center, ap.body.location)
        return abs(d - radius) < maxOf(3.0, radius * 0.2) && abs(ap.body.location.altitude.meters - center.altitude.meters) < 5.0
    }
}
