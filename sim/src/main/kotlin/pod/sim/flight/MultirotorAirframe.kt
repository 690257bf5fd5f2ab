package pod.sim.flight

import kotlin.math.abs
import kotlin.math.atan2
import kotlin.math.cos
import kotlin.math.hypot
import kotlin.math.min
import kotlin.math.sin
import kotlin.math.sqrt

/**
 * A kinematic multirotor: horizontal velocity steered towards the guidance's goal with bounded
 * acceleration (slowing down so it stops on a target), vertical speed bounded by the climb and
 * descent rates, heading turned towards the direction of travel at a bounded yaw rate.
 */
internal object MultirotorAirframe : Airframe {
    private const val VERTICAL_ACCEL = 5.0 // m/s², how fast the climb rate follows its demand
    private const val LAND_SLOW_HEIGHT = 10.0 // m; ArduCopter's LAND_ALT_LOW: below it, land at LAND_SPEED
    /** m/s; a multirotor disarmed in the air, or with its throttle at minimum, drops. */
    const val FALL_SPEED = 10.0

    override fun step(body: Body, guidance: Guidance, perf: Performance, ground: Double, armed: Boolean, dt: Double): Body {
        val alt = body.location.altitude.meters
        if (!armed || guidance == Guidance.Idle) {
            if (body.onGround) return body.copy(velocityNorth = 0.0, velocityEast = 0.0, velocityDown = 0.0, airspeed = 0.0, throttle = 0)
            if (!armed) return verticalOnly(body, ground, FALL_SPEED, dt, throttle = 0)
        }
        var target: Pair<Double, Double> = 0.0 to 0.0 // desired velocity north/east
        var targetAlt = alt
        var climbLimit = perf.climb
        var descentLimit = perf.descent
        when (guidance) {
            Guidance.Idle -> Unit
            is Guidance.Climb -> targetAlt = guidance.altitude
            is Guidance.GoTo -> {
                target = approach(body, northEast(body.location, guidance.target), guidance.speed ?: perf.cruise, perf, guidance.through, guidance.throughRadius)
                targetAlt = guidance.target.altitude.meters
            }
            is Guidance.Loiter -> {
                targetAlt = guidance.center.altitude.meters
                target = if (guidance.radius < 0.5) {
                    approach(body, northEast(body.location, guidance.center), perf.cruise, perf)
                } else {
                    circle(body, guidance, perf)
                }
            }
            is Guidance.Land -> {
                val over = guidance.at
                val (n, e) = if (over == null) 0.0 to 0.0 else northEast(body.location, over)
                if (hypot(n, e) > 1.0) {
                    target = approach(body, n to e, perf.cruise, perf) // fly over the spot before descending
                } else {
                    targetAlt = ground - 1.0
                    descentLimit = if (alt - ground > LAND_SLOW_HEIGHT) perf.descent else perf.landSpeed
                    climbLimit = 0.0
                    target = approach(body, n to e, perf.cruise, perf)
                }
            }
            is Guidance.Descend -> {
                targetAlt = ground - 1.0
                descentLimit = guidance.rate
                climbLimit = 0.0
                target = guidance.over?.let { approach(body, northEast(body.location, it), perf.cruise, perf) } ?: (0.0 to 0.0)
            }
            is Guidance.Track -> return step(body, Guidance.GoTo(guidance.to), perf, ground, armed, dt)
            is Guidance.Cruise, is Guidance.Glide -> Unit // a multirotor with nobody on the sticks holds position
        }
        if (body.onGround && targetAlt <= ground + 0.2) {
            return body.copy(velocityNorth = 0.0, velocityEast = 0.0, velocityDown = 0.0, airspeed = 0.0, throttle = if (armed) 5 else 0)
        }
        if (body.onGround) target = 0.0 to 0.0 // lift off vertically before moving sideways

        // Horizontal: move the velocity towards the demand, at most acceleration × dt.
        val dvN = target.first - body.velocityNorth
        val dvE = target.second - body.velocityEast
        val dv = hypot(dvN, dvE)
        val maxDv = perf.acceleration * dt
        val scale = if (dv > maxDv) maxDv / dv else 1.0
        val vN = body.velocityNorth + dvN * scale
        val vE = body.velocityEast + dvE * scale

        // Vertical: a climb rate that slows down to stop on the target altitude.
        val err = targetAlt - alt
        val wanted = (if (err >= 0) min(climbLimit, sqrt(2 * VERTICAL_ACCEL * 0.5 * err)) else -min(descentLimit, sqrt(2 * VERTICAL_ACCEL * 0.5 * -err)))
            .let { if (abs(err) < 0.05) 0.0 else it }
        val climbNow = -body.velocityDown
        val climb = climbNow + (wanted - climbNow).coerceIn(-VERTICAL_ACCEL * dt, VERTICAL_ACCEL * dt)
        var newAlt = alt + climb * dt
        if (err > 0 && newAlt > targetAlt) newAlt = targetAlt
        if (err < 0 && newAlt < targetAlt) newAlt = targetAlt

        val touchdown = newAlt <= ground && climb <= 0
        if (touchdown) {
            return body.copy(
                location = atAltitude(moved(body.location, vN * dt, vE * dt, 0.0), ground),
                velocityNorth = 0.0, velocityEast = 0.0, velocityDown = 0.0, airspeed = 0.0, onGround = true, throttle = 5,
            )
        }
        val speed = hypot(vN, vE)
        val course = wrap360(Math.toDegrees(atan2(vE, vN)))
        val wantedHeading = if (speed > 1.0) course else body.heading
        val maxTurn = perf.yawRate * dt
        val heading = wrap360(body.heading + turn(body.heading, wantedHeading).coerceIn(-maxTurn, maxTurn))
        return Body(
            location = atAltitude(moved(body.location, vN * dt, vE * dt, 0.0), newAlt),
            velocityNorth = vN, velocityEast = vE, velocityDown = -climb,
            heading = heading, airspeed = speed, onGround = false,
            throttle = (50 + 8 * climb + 2 * speed).toInt().coerceIn(0, 100),
        )
    }

    /**
     * The velocity that takes the vehicle [offset] (north, east metres) away and stops it there, or
     * when [through] > 0, comes within [throughRadius] of it at [through] m/s.
     */
    private fun approach(body: Body, offset: Pair<Double, Double>, speed: Double, perf: Performance, through: Double = 0.0, throughRadius: Double = 0.0): Pair<Double, Double> {
        val (n, e) = offset
        val d = hypot(n, e)
        if (d < 0.05) return 0.0 to 0.0
        val v = if (through > 0) {
            minOf(speed, sqrt(through * through + 2 * perf.acceleration * 0.8 * (d - throughRadius).coerceAtLeast(0.0)))
        } else {
            minOf(speed, sqrt(2 * perf.acceleration * 0.8 * d), d / 0.2)
        }
        return n / d * v to e / d * v
    }

    /** The velocity that flies a circle: tangential at the circle speed, radial to correct the radius. */
    private fun circle(body: Body, g: Guidance.Loiter, perf: Performance): Pair<Double, Double> {
        val (n, e) = northEast(g.center, body.location)
        val d = hypot(n, e)
        if (d < 0.5) return approach(body, northEast(body.location, moved(g.center, g.radius, 0.0, 0.0)), perf.cruise, perf)
        val theta = atan2(e, n)
        val sign = if (g.clockwise) 1.0 else -1.0
        // A commanded circle speed (PX4's orbit, already limited by the autopilot) may exceed the
        // cruise speed; the approach to the circle stays at cruise speed. Otherwise ArduCopter's
        // circle: the circle rate, at most the waypoint speed and √(½·accel·r), which keeps half
        // the acceleration for turning (libraries/AC_WPNav/AC_Circle.cpp, calc_velocities).
        val tangential = g.speed ?: minOf(perf.cruise, g.radius * Math.toRadians(perf.circleRate), sqrt(0.5 * perf.acceleration * g.radius))
        val limit = maxOf(perf.cruise, tangential)
        val radial = (-(d - g.radius) * 0.5).coerceIn(-perf.cruise, perf.cruise)
        var vN = cos(theta) * radial + cos(theta + sign * Math.PI / 2) * tangential
        var vE = sin(theta) * radial + sin(theta + sign * Math.PI / 2) * tangential
        val v = hypot(vN, vE)
        if (v > limit) {
            vN *= limit / v
            vE *= limit / v
        }
        return vN to vE
    }

    private fun verticalOnly(body: Body, ground: Double, sink: Double, dt: Double, throttle: Int): Body {
        val alt = body.location.altitude.meters
        val newAlt = (alt - sink * dt).coerceAtLeast(ground)
        val landed = newAlt <= ground
        return body.copy(
            location = atAltitude(body.location, newAlt),
            velocityNorth = 0.0, velocityEast = 0.0, velocityDown = if (landed) 0.0 else sink,
            airspeed = 0.0, onGround = landed, throttle = throttle,
        )
    }
}
