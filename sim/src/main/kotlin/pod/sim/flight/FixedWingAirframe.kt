package pod.sim.flight

import kotlin.math.atan
import kotlin.math.cos
import kotlin.math.hypot
import kotlin.math.max
import kotlin.math.min
import kotlin.math.sin
import kotlin.math.tan

/**
 * A kinematic plane: it never flies slower than its minimum airspeed, turns no faster than a
 * coordinated turn at its bank limit allows (rate = g·tan(bank)/v), climbs and sinks at bounded
 * rates, circles instead of hovering, takes off along its heading and lands by gliding down to a
 * point, then rolls to a stop.
 */
internal object FixedWingAirframe : Airframe {
    private const val G = 9.80665
    private const val TAKEOFF_ACCEL = 3.0 // m/s² on the runway at full throttle
    private const val ROLLOUT_DECEL = 2.0 // m/s² braking after touchdown
    private const val SPEED_ACCEL = 2.0 // m/s² how fast airspeed follows its demand in the air
    private const val VERTICAL_ACCEL = 3.0 // m/s²
    private const val DISARMED_SINK = 3.0 // m/s; a plane with the motor off glides down

    /** Radius of the tightest turn at [speed] m/s within [bankLimit] degrees of bank. */
    fun turnRadius(speed: Double, bankLimit: Double): Double = speed * speed / (G * tan(Math.toRadians(bankLimit)))

    override fun step(body: Body, guidance: Guidance, perf: Performance, ground: Double, armed: Boolean, dt: Double): Body {
        if (body.onGround) return onGround(body, guidance, perf, armed, dt)
        val alt = body.location.altitude.meters
        val cruise = perf.cruise.coerceIn(perf.minAirspeed, perf.maxAirspeed)
        var heading = body.heading
        var targetAlt = alt
        var speed = cruise
        var sinkLimit = perf.descent
        var spiralling = false
        when (guidance) {
            Guidance.Idle -> Unit
            is Guidance.Climb -> targetAlt = guidance.altitude
            is Guidance.GoTo -> {
                if (horizontalDistance(body.location, guidance.target) > 1.0) heading = bearing(body.location, guidance.target)
                targetAlt = guidance.target.altitude.meters
                guidance.speed?.let { speed = it }
            }
            is Guidance.Track -> {
                heading = trackCourse(body, guidance, perf)
                targetAlt = guidance.to.altitude.meters
            }
            is Guidance.Loiter -> {
                heading = loiterCourse(body, guidance, perf)
                targetAlt = guidance.center.altitude.meters
            }
            is Guidance.Land -> {
                val at = guidance.at ?: body.location
                speed = min(cruise, perf.minAirspeed * 1.3)
                val dist = horizontalDistance(body.location, at)
                val height = alt - ground
                // The sink rate that would put the wheels on the spot; too steep means circle down first.
                val needed = if (dist < 1.0) Double.MAX_VALUE else height / (dist / speed)
                spiralling = if (body.spiralling) needed > perf.descent * 0.7 else needed > perf.descent
                if (spiralling) {
                    heading = loiterCourse(body, Guidance.Loiter(at, perf.loiterRadius), perf)
                    targetAlt = ground
                } else {
                    if (dist > 10.0) heading = bearing(body.location, at)
                    targetAlt = ground - 1.0
                    sinkLimit = min(perf.descent, needed)
                }
            }
            is Guidance.Glide -> {
                heading = guidance.heading
                speed = min(cruise, perf.minAirspeed * 1.3)
                targetAlt = guidance.altitude
                sinkLimit = guidance.sinkLimit
            }
            is Guidance.Cruise -> {
                heading = guidance.heading
                targetAlt = guidance.altitude
            }
            is Guidance.Descend -> {
                // A plane never gets this (its modes keep flying); glide down straight ahead.
                targetAlt = ground - 1.0
                sinkLimit = min(perf.descent, guidance.rate)
            }
        }
        if (!armed) {
            targetAlt = ground - 1.0
            sinkLimit = DISARMED_SINK
            speed = perf.minAirspeed
        }
        val airspeed = body.airspeed + (speed.coerceIn(perf.minAirspeed, perf.maxAirspeed) - body.airspeed).coerceIn(-SPEED_ACCEL * dt, SPEED_ACCEL * dt)
        val rate = Math.toDegrees(G * tan(Math.toRadians(perf.bankLimit)) / max(airspeed, 1.0))
        val newHeading = wrap360(body.heading + turn(body.heading, heading).coerceIn(-rate * dt, rate * dt))
        val err = targetAlt - alt
        val wanted = (err * 0.5).coerceIn(-sinkLimit, perf.climb)
        val climbNow = -body.velocityDown
        val climb = climbNow + (wanted - climbNow).coerceIn(-VERTICAL_ACCEL * dt, VERTICAL_ACCEL * dt)
        val h = Math.toRadians(newHeading)
        val vN = cos(h) * airspeed
        val vE = sin(h) * airspeed
        val newAlt = alt + climb * dt
        val moved = moved(body.location, vN * dt, vE * dt, 0.0)
        if (newAlt <= ground) {
            // Touchdown: the wheels take the weight; the rollout continues on the ground.
            return body.copy(
                location = atAltitude(moved, ground), velocityNorth = vN, velocityEast = vE, velocityDown = 0.0,
                heading = newHeading, airspeed = airspeed, onGround = true, throttle = 0, spiralling = false,
            )
        }
        return Body(
            location = atAltitude(moved, newAlt), velocityNorth = vN, velocityEast = vE, velocityDown = -climb,
            heading = newHeading, airspeed = airspeed, onGround = false, spiralling = spiralling,
            throttle = if (!armed) 0 else (45 + 10 * climb + 2 * (airspeed - perf.minAirspeed)).toInt().coerceIn(0, 100),
        )
    }

    private fun onGround(body: Body, guidance: Guidance, perf: Performance, armed: Boolean, dt: Double): Body {
        val ground = body.location.altitude.meters
        if (armed && guidance is Guidance.Climb && guidance.altitude > ground + 1) {
            // Take-off run along the heading until the plane can fly, then rotate and climb.
            val speed = body.airspeed + TAKEOFF_ACCEL * dt
            val h = Math.toRadians(body.heading)
            val moved = moved(body.location, cos(h) * speed * dt, sin(h) * speed * dt, 0.0)
            val flying = speed >= perf.minAirspeed * 1.1
            return body.copy(
                location = if (flying) atAltitude(moved, ground + 0.1) else moved,
                velocityNorth = cos(h) * speed, velocityEast = sin(h) * speed, velocityDown = if (flying) -1.0 else 0.0,
                airspeed = speed, onGround = !flying, throttle = 100,
            )
        }
        // Rolling out (or standing still): brake to a stop along the heading.
        val speed = (body.airspeed - ROLLOUT_DECEL * dt).coerceAtLeast(0.0)
        if (speed == 0.0) return body.copy(velocityNorth = 0.0, velocityEast = 0.0, velocityDown = 0.0, airspeed = 0.0, throttle = 0)
        val h = Math.toRadians(body.heading)
        return body.copy(
            location = moved(body.location, cos(h) * speed * dt, sin(h) * speed * dt, 0.0),
            velocityNorth = cos(h) * speed, velocityEast = sin(h) * speed, velocityDown = 0.0, airspeed = speed, throttle = 0,
        )
    }

    /**
     * The course that converges on the line [Guidance.Track.from]–[Guidance.Track.to]: towards the
     * point on the line a couple of turn radii beyond the plane's projection onto it (as an L1
     * controller does), straight at the end once that is nearer.
     */
    private fun trackCourse(body: Body, g: Guidance.Track, perf: Performance): Double {
        val (ln, le) = northEast(g.from, g.to)
        val length = hypot(ln, le)
        if (length < 1.0) return bearing(body.location, g.to)
        val (n, e) = northEast(g.from, body.location)
        val lookahead = 2 * turnRadius(max(body.airspeed, perf.minAirspeed), perf.bankLimit)
        val along = (n * ln + e * le) / length + lookahead
        if (along >= length) return bearing(body.location, g.to)
        val aimN = ln * along / length - n
        val aimE = le * along / length - e
        return wrap360(Math.toDegrees(kotlin.math.atan2(aimE, aimN)))
    }

    /**
     * The course that converges on a circle around the centre: tangential on the circle, turning
     * in towards it from outside (up to straight at the centre) and out from inside.
     */
    private fun loiterCourse(body: Body, g: Guidance.Loiter, perf: Performance): Double {
        // A circle tighter than the plane can turn would never converge; widen it to what it can fly.
        val radius = max(g.radius, turnRadius(max(body.airspeed, perf.minAirspeed), perf.bankLimit) * 1.25)
        val (n, e) = northEast(g.center, body.location)
        val d = hypot(n, e)
        if (d < 1.0) return body.heading
        val theta = Math.toDegrees(kotlin.math.atan2(e, n))
        val alpha = Math.toDegrees(atan(2.0 * (d - radius) / radius)).coerceIn(-80.0, 90.0)
        return wrap360(if (g.clockwise) theta + 90 + alpha else theta - 90 - alpha)
    }
}
