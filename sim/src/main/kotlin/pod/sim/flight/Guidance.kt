package pod.sim.flight

import pod.core.units.Location

/**
 * What the autopilot asks the airframe to do during one step. Altitudes are above mean sea level;
 * the airframe decides how (a multirotor stops and hovers, a plane keeps flying and circles).
 */
internal sealed interface Guidance {
    /** On the ground with the motors off or idling; in the air a disarmed vehicle falls. */
    data object Idle : Guidance

    /** Take off and climb to [altitude]: straight up for a multirotor, along the heading for a plane. */
    data class Climb(val altitude: Double) : Guidance

    /**
     * Fly towards [target] at [speed] m/s (null: the cruise speed); a multirotor stops there, or,
     * with [through] > 0, slows down to no less than [through] m/s by [throughRadius] metres from
     * it (a mission waypoint it turns on to the next from there).
     */
    data class GoTo(val target: Location, val speed: Double? = null, val through: Double = 0.0, val throughRadius: Double = 0.0) : Guidance

    /**
     * A plane flying the line from [from] to [to] (ArduPlane's crosstrack navigation towards a far
     * guided point, see Activity.GoTo); a multirotor flies straight to [to].
     */
    data class Track(val from: Location, val to: Location) : Guidance

    /**
     * Stay at [center]: a multirotor hovers on it (or flies a circle when [radius] > 0, at [speed]
     * m/s along it when given, else at its circle rate), a plane circles it at [radius] (at least
     * the tightest circle it can turn).
     */
    data class Loiter(val center: Location, val radius: Double, val clockwise: Boolean = true, val speed: Double? = null) : Guidance

    /** Land: a multirotor descends (flying over [at] first when given), a plane glides down to [at]. */
    data class Land(val at: Location?) : Guidance

    /**
     * Descend at [rate] m/s to the ground and stay there: a multirotor whose throttle stick is at
     * minimum, holding its position over [over] (null: braking to a stop wherever that is).
     */
    data class Descend(val over: Location?, val rate: Double) : Guidance

    /**
     * A plane on a landing glide: fly [heading] at landing speed towards [altitude] (it may be below
     * the ground), sinking no faster than [sinkLimit] m/s.
     */
    data class Glide(val heading: Double, val altitude: Double, val sinkLimit: Double) : Guidance

    /** Hold [heading] and [altitude] (a plane in a manual mode with nobody on the sticks). */
    data class Cruise(val heading: Double, val altitude: Double) : Guidance
}

/** The kinematic state of an airframe: position, velocity over the ground, heading, airspeed. */
internal data class Body(
    val location: Location,
    val velocityNorth: Double = 0.0,
    val velocityEast: Double = 0.0,
    val velocityDown: Double = 0.0,
    val heading: Double = 0.0,
    val airspeed: Double = 0.0,
    val onGround: Boolean = true,
    val throttle: Int = 0,
    /** A plane on a landing approach is spiralling down to lose height (it was too high to glide in). */
    val spiralling: Boolean = false,
)

/** Speeds, rates and radii an airframe flies with, read from the autopilot's parameters. */
internal data class Performance(
    /** Horizontal cruise speed (multirotor) or cruise airspeed (plane), m/s. */
    val cruise: Double,
    /** Climb rate, m/s. */
    val climb: Double,
    /** Descent rate in flight, m/s. */
    val descent: Double,
    /** Final descent rate when landing (multirotor), m/s. */
    val landSpeed: Double = 0.5,
    /** Horizontal acceleration limit, m/s². */
    val acceleration: Double = 2.5,
    /** Minimum airspeed in the air (plane), m/s. */
    val minAirspeed: Double = 0.0,
    /** Maximum airspeed (plane), m/s. */
    val maxAirspeed: Double = 0.0,
    /** Bank limit (plane), degrees. */
    val bankLimit: Double = 45.0,
    /** Default loiter radius (plane), m. */
    val loiterRadius: Double = 60.0,
    /** Turn rate when a multirotor circles or pivots, degrees per second. */
    val circleRate: Double = 20.0,
    /** Yaw rate of a multirotor, degrees per second. */
    val yawRate: Double = 90.0,
)

/** The physics of one airframe kind: advances a [Body] under a [Guidance] by a fixed step. */
internal interface Airframe {
    /** The body after [dt] seconds flying [guidance], with the ground at [ground] metres AMSL. */
    fun step(body: Body, guidance: Guidance, perf: Performance, ground: Double, armed: Boolean, dt: Double): Body
}
