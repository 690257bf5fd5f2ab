package pod.sim.autopilot

import pod.core.vehicle.Severity
import pod.core.units.Location
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType
import pod.mavlink.mission.MissionMessage
import pod.mavlink.mission.MissionType
import pod.mavlink.protocol.Step
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.vehicle.MissionServer
import pod.sim.PhotoEvent
import pod.sim.SimState
import pod.sim.flight.Airframe
import pod.sim.flight.Body
import pod.sim.flight.FixedWingAirframe
import pod.sim.flight.Guidance
import pod.sim.flight.MultirotorAirframe
import pod.sim.flight.Performance
import pod.sim.flight.atAltitude
import pod.sim.flight.horizontalDistance
import pod.sim.flight.moved
import pod.sim.world.SimWorld
import pod.core.units.deg
import pod.core.units.m
import kotlin.math.cos
import kotlin.math.sin
import kotlin.time.Duration.Companion.seconds

/**
 * The simulated autopilot: modes, arming, commands, missions, parameters and the physics, as a
 * pure state machine. [step] advances simulated time by a fixed step; commands and messages go in
 * through [commands] and [params]; what should be sent collects in [drain]. No coroutines, no
 * clocks: tests drive it by stepping time.
 */
internal class SimAutopilot(
    val autopilot: Autopilot,
    val type: VehicleType,
    systemId: Int,
    home: Location,
    charge: Double,
    val missionServer: MissionServer,
    /** Simulated seconds after boot before the GPS has a 3D fix and the estimator sets its origin (and home). */
    private val readyAfter: Double = 2.0,
    /** Simulated seconds after boot before the sensors pass the pre-arm checks (never before [readyAfter] matters). */
    private val sensorsReadyAfter: Double = readyAfter,
    /** Simulated seconds after boot before the estimator's position is good enough to navigate (ArduCopter's position_ok). */
    private val navigationReadyAfter: Double = sensorsReadyAfter,
    /** The ground under it and the objects its camera sees: flat at [home]'s altitude unless given. */
    val world: SimWorld = SimWorld(home.altitude.meters),
) {
    val multirotor: Boolean = type.isMultirotor || type == VehicleType.OTHER
    val isPx4: Boolean get() = autopilot == Autopilot.PX4
    private val airframe: Airframe = if (multirotor) MultirotorAirframe else FixedWingAirframe
    val params = SimParameters(autopilot, ParamTables.forVehicle(autopilot, type, systemId))
    val commands = Commands(this)
    val paramService = ParamService(this)
    val mission = MissionRunner(this)
    val camera = Camera()
    val fence: Geofence = Geofence.of(this)

    /** Elevation AMSL in metres of the ground straight below the vehicle (the terrain's, or flat). */
    val ground: Double get() = world.groundAt(body.location)

    var time = 0.0; private set
    var body = Body(home, heading = 0.0); internal set
    var home: Location = home; internal set
    var charge = charge; private set
    var armed = false; private set
    var modeName: String = if (isPx4) "AUTO.LOITER" else if (multirotor) "STABILIZE" else "MANUAL"; private set
    var activity: Activity = Activity.Parked; internal set

    /**
     * ArduPlane GUIDED's loiter radius from a DO_REPOSITION's param3, m (0: WP_LOITER_RAD). It
     * lasts while the plane stays in GUIDED: ModeGuided::_enter sets active_radius_m to 0, and
     * ModeGuided::set_radius_and_direction is the only other writer (ArduPlane/mode_guided.cpp).
     */
    var guidedRadius = 0.0

    /** Speed overrides from DO_CHANGE_SPEED (m/s), null = the parameter's value. */
    var cruiseOverride: Double? = null
    var climbOverride: Double? = null
    var descentOverride: Double? = null

    private val outbox = ArrayList<SimOutput>()
    private var disarmAt: Double? = null
    private var landedByLanding = false
    private var lastCurrent = -1
    val reached = ArrayList<Int>()
    val photos = ArrayList<PhotoEvent>()

    /**
     * Whether a ground station may clear [type]'s list now (the [missionServer]'s `clearAllowed`).
     * ArduPilot will not clear a mission it is flying: AP_Mission::clear refuses while armed and
     * MISSION_RUNNING (in AUTO), and MissionItemProtocol::handle_mission_clear_all answers ERROR.
     */
    fun allowsClearing(type: MissionType): Boolean = isPx4 || type != MissionType.MISSION || !(armed && modeName == "AUTO" && mission.running)

    /**
     * True once the simulated GPS has a fix and the estimator has set its origin. ArduPilot has no
     * home before that: Copter::update_home_from_EKF (ArduCopter/commands.cpp) sets home to the
     * current location only once AP_AHRS has an origin, and GCS_MAVLINK::send_home_position sends
     * nothing while AP_AHRS::home_is_set() is false.
     */
    val positionReady: Boolean get() = time >= readyAfter

    /**
     * True once the estimator's position is good enough for the modes that navigate (ArduCopter's
     * Copter::position_ok); before, ArduCopter refuses GUIDED, AUTO, BRAKE… with "requires position".
     */
    val navigationReady: Boolean get() = time >= maxOf(readyAfter, navigationReadyAfter)

    /** True once the inertial sensors have settled (ArduPilot SITL: "Accels inconsistent" until then). */
    val sensorsReady: Boolean get() = time >= sensorsReadyAfter

    /** The messages to send, oldest first; empties the queue. */
    fun drain(): List<SimOutput> = outbox.toList().also { outbox.clear() }

    internal fun emit(output: SimOutput) {
        outbox += output
    }

    internal fun text(severity: Severity, text: String) = emit(SimOutput.Text(severity, text))

    /** A snapshot for telemetry. */
    fun state(): SimState = SimState(
        location = body.location, home = home,
        velocityNed = Triple(body.velocityNorth, body.velocityEast, body.velocityDown),
        headingDeg = body.heading, charge = charge, armed = armed, landedState = landedState(),
        customMode = FlightModes.customMode(autopilot, type, modeName) ?: 0, modeName = modeName,
        airspeed = body.airspeed, throttle = body.throttle, missionCurrent = missionServer.current, positionReady = positionReady,
        target = target(), groundAltitude = ground.m, time = time.seconds, crashed = crashed,
    )

    private fun target(): Location? = when (val a = activity) {
        is Activity.GoTo -> a.target
        Activity.Mission -> mission.target
        else -> null
    }

    /**
     * Hands a mission-protocol message from a ground station to the mission server at [now] (the
     * server's clock) and returns its step (replies, wake time), reacting to the list as it is afterwards
     * ([missionChanged]). MISSION_SET_CURRENT while an ArduPilot vehicle flies its mission restarts
     * the item named, even the one it is flying: AP_Mission::set_current_cmd stops the current nav
     * command and advance_current_nav_cmd reads the item from storage again, at once, in the
     * message handler (libraries/AP_Mission/AP_Mission.cpp); AP_Mission::replace_cmd says a
     * rewritten active item has "no effect until the command is restarted". So an upload that
     * rewrote the item being flown takes effect with it.
     */
    fun onMissionMessage(message: MissionMessage, now: Long): Step<MissionMessage, Nothing> {
        val replies = missionServer.onMessage(message, now)
        missionChanged()
        if (message is MissionMessage.SetCurrent && !isPx4 && activity == Activity.Mission) mission.restart()
        return replies
    }

    private fun landedState(): LandedState = when {
        body.onGround && body.airspeed < 0.5 -> LandedState.ON_GROUND
        body.onGround -> if (activity is Activity.Takeoff) LandedState.TAKEOFF else LandedState.LANDING
        activity is Activity.Takeoff -> LandedState.TAKEOFF
        activity is Activity.Landing || (activity as? Activity.Returning)?.plan?.landing == true || mission.landing -> LandedState.LANDING
        else -> LandedState.IN_AIR
    }

    /** Flight performance from the parameters and any DO_CHANGE_SPEED overrides. */
    fun performance(): Performance = when {
        isPx4 && multirotor -> Performance(
            cruise = cruiseOverride ?: params["MPC_XY_CRUISE"], climb = climbOverride ?: params["MPC_Z_VEL_MAX_UP"],
            descent = descentOverride ?: params["MPC_Z_VEL_MAX_DN"], landSpeed = params["MPC_LAND_SPEED"], acceleration = params["MPC_ACC_HOR"],
        )
        isPx4 -> Performance(
            cruise = cruiseOverride ?: params["FW_AIRSPD_TRIM"], climb = climbOverride ?: params["FW_T_CLMB_MAX"],
            descent = descentOverride ?: params["FW_T_SINK_MAX"], minAirspeed = params["FW_AIRSPD_MIN"], maxAirspeed = params["FW_AIRSPD_MAX"],
            bankLimit = params["FW_R_LIM"], loiterRadius = params["NAV_LOITER_RAD"],
        )
        multirotor -> Performance(
            cruise = cruiseOverride ?: (params["WPNAV_SPEED"] / 100), climb = climbOverride ?: (params["WPNAV_SPEED_UP"] / 100),
            descent = descentOverride ?: (params["WPNAV_SPEED_DN"] / 100), landSpeed = params["LAND_SPEED"] / 100,
            acceleration = params["WPNAV_ACCEL"] / 100, circleRate = kotlin.math.abs(params["CIRCLE_RATE"]).coerceAtLeast(1.0),
        )
        else -> Performance(
            cruise = cruiseOverride ?: params["AIRSPEED_CRUISE"], climb = climbOverride ?: params["TECS_CLMB_MAX"],
            descent = descentOverride ?: params["TECS_SINK_MAX"], minAirspeed = params["AIRSPEED_MIN"], maxAirspeed = params["AIRSPEED_MAX"],
            bankLimit = params["ROLL_LIMIT_DEG"], loiterRadius = kotlin.math.abs(params["WP_LOITER_RAD"]),
        )
    }

    /** A plane's loiter radius (positive) and direction. */
    fun loiterRadius(): Pair<Double, Boolean> = when {
        isPx4 -> params["NAV_LOITER_RAD"] to true
        multirotor -> 0.0 to true
        else -> params["WP_LOITER_RAD"].let { kotlin.math.abs(it) to (it >= 0) }
    }

    /** Acceptance radius for waypoints: [requested] when positive, else the flavour's parameter. */
    fun acceptanceRadius(requested: Float): Double {
        if (requested > 0) return requested.toDouble()
        return when {
            isPx4 && multirotor -> params["NAV_ACC_RAD"]
            isPx4 -> maxOf(params["NAV_ACC_RAD"], FixedWingAirframe.turnRadius(params["FW_AIRSPD_TRIM"], params["FW_R_LIM"]))
            multirotor -> params["WPNAV_RADIUS"] / 100
            else -> params["WP_RADIUS"]
        }
    }

    /** Advances simulated time by [dt] seconds. */
    fun step(dt: Double) {
        val wasReady = positionReady
        time += dt
        // Setting home announces it (AP_AHRS::set_home has GCS send HOME_POSITION to every link).
        if (positionReady && !wasReady) emit(SimOutput.HomeChanged)
        charge = (if (armed) charge - dt / FULL_DRAIN_SECONDS else charge + dt / FULL_RECHARGE_SECONDS).coerceIn(0.0, 1.0)
        missionChanged()
        val guidance = guidance()
        val braking = (activity as? Activity.Hold)?.braking
        body = airframe.step(body, guidance, performance().let { p -> if (braking == null) p else p.copy(acceleration = maxOf(p.acceleration, braking)) }, ground, armed, dt)
        checkTerrainClearance(guidance)
        afterStep()
        fence.step()
        for (shot in camera.step(time, body.location, if (activity == Activity.Mission) missionServer.current else null)) {
            val photo = shot.copy(heading = body.heading.deg, heightAboveGround = (body.location.altitude.meters - ground).m, detected = world.detect(body.location, body.heading))
            photos += photo
            emit(SimOutput.Photo(photo))
        }
        commands.step(dt)
        if (missionServer.current != lastCurrent) {
            lastCurrent = missionServer.current
            // PX4's mission manager announces a new current item; ArduPilot only streams
            // MISSION_CURRENT when asked (see SimVehicleConfig.defaultStreamRates) and answers
            // MISSION_SET_CURRENT with one.
            if (isPx4) emit(SimOutput.MissionCurrent(lastCurrent))
        }
    }

    private fun guidance(): Guidance = when (val a = activity) {
        Activity.Parked -> Guidance.Idle
        is Activity.Takeoff -> if (armed) Guidance.Climb(a.altitude) else Guidance.Idle
        is Activity.Hold -> Guidance.Loiter(a.center, a.radius, a.clockwise)
        is Activity.GoTo -> {
            val (radius, clockwise) = if (a.radius > 0) a.radius to a.clockwise else loiterRadius()
            when {
                multirotor -> Guidance.GoTo(a.target, a.speed)
                a.from != null && horizontalDistance(body.location, a.target) > 3 * radius -> Guidance.Track(a.from, a.target)
                else -> Guidance.Loiter(a.target, radius, clockwise)
            }
        }
        is Activity.Orbit -> Guidance.Loiter(a.center, a.radius, a.clockwise, a.speed)
        is Activity.Returning -> a.plan.guidance(body)
        is Activity.Landing -> Guidance.Land(a.at)
        Activity.Mission -> mission.guidance()
        is Activity.Cruise -> Guidance.Cruise(a.heading, a.altitude)
        is Activity.Descending -> Guidance.Descend(a.over, a.rate)
    }

    /**
     * What the simulator did to a vehicle it saw fly into the ground, or null: flying on (not
     * climbing out of a take-off, not landing) lower than [TERRAIN_CLEARANCE] above the ground
     * while moving over it. Not an autopilot's behaviour but the world's: the vehicle disarms and
     * drops, saying "Crash: flew into terrain" (CRITICAL), so a ground station that sends a vehicle
     * along the ground sees its flight fail instead of a track that no real vehicle could fly.
     */
    var crashed: String? = null
        private set

    private fun checkTerrainClearance(guidance: Guidance) {
        if (!armed || body.onGround || guidance is Guidance.Climb || guidance is Guidance.Land || guidance is Guidance.Glide) return
        val state = landedState()
        if (state == LandedState.TAKEOFF || state == LandedState.LANDING) return
        val moving = kotlin.math.hypot(body.velocityNorth, body.velocityEast) > TERRAIN_MOVING_SPEED
        if (!moving || body.location.altitude.meters - ground >= TERRAIN_CLEARANCE) return
        crashed = "flew into terrain"
        text(Severity.CRITICAL, "Crash: flew into terrain")
        activity = Activity.Parked
        disarm()
    }

    private fun afterStep() {
        when (val a = activity) {
            is Activity.Takeoff -> if (takeoffReached(a.altitude)) {
                // Take-off done, the mode takes over: GUIDED holds, LOITER with no stick input sinks.
                if (a.then != null) setMode(a.then) else enterMode(modeName)
            }
            is Activity.GoTo -> if (multirotor && horizontalDistance(body.location, a.target) < 0.5 &&
                kotlin.math.abs(body.location.altitude.meters - a.target.altitude.meters) < 0.5
            ) {
                activity = Activity.Hold(a.target, 0.0)
            }
            else -> Unit
        }
        val landing = activity is Activity.Landing || (activity as? Activity.Returning)?.plan?.landing == true || mission.landing
        if (body.onGround && body.airspeed < 0.1 && activity != Activity.Parked && activity !is Activity.Takeoff && landing) {
            landedByLanding = true
            if (activity == Activity.Mission) mission.touchedDown() else activity = Activity.Parked
        }
        if (activity == Activity.Mission && mission.finishedOnGround) activity = Activity.Parked
        // Touched down with the throttle at minimum: landed, and disarmed after DISARM_DELAY.
        if (activity is Activity.Descending && body.onGround && body.airspeed < 0.1) activity = Activity.Parked
        autoDisarm()
    }

    private fun autoDisarm() {
        val parked = armed && body.onGround && body.airspeed < 0.1 && (activity == Activity.Parked || (activity == Activity.Mission && !mission.wantsToFly()))
        if (!parked) {
            disarmAt = null
            if (!body.onGround) landedByLanding = false
            return
        }
        val at = disarmAt ?: run {
            val delay = when {
                isPx4 -> if (landedByLanding) params["COM_DISARM_LAND"] else params["COM_DISARM_PRFLT"]
                multirotor -> if (landedByLanding) 1.0 else params["DISARM_DELAY"].takeIf { it > 0 } ?: -1.0
                else -> if (landedByLanding) params["LAND_DISARMDELAY"].takeIf { it > 0 } ?: -1.0 else -1.0
            }
            if (delay < 0) return
            (time + delay).also { disarmAt = it }
        }
        if (time >= at) {
            disarm()
            text(Severity.INFO, if (isPx4) "Disarmed by auto disarm" else "Disarming motors")
        }
    }

    /**
     * Reacts to the mission list as it is now; called every step and right after each mission
     * message, since ArduPlane notices within one loop (ModeAuto::update, ArduPlane/mode_auto.cpp):
     * a plane in AUTO with no mission to run switches to RTL.
     */
    fun missionChanged() {
        if (!isPx4 && !multirotor && modeName == "AUTO" && !mission.hasMission()) {
            setMode("RTL")
            text(Severity.INFO, "Aircraft in auto without a running mission")
        }
    }

    /** Arms (checks are the caller's business). */
    fun arm() {
        armed = true
        landedByLanding = false
        disarmAt = null
        if (activity == Activity.Parked && Modes.behaviour(autopilot, type, modeName) == Behaviour.TAKEOFF) enterMode(modeName)
    }

    /** Disarms; in the air the vehicle falls (a multirotor) or glides down (a plane). */
    fun disarm() {
        armed = false
        disarmAt = null
        if (body.onGround) activity = Activity.Parked
    }

    /** Switches to mode [name] and starts what it does (the caller checked that it may). */
    fun setMode(name: String) {
        // Selecting the mode it is in enters nothing (ArduPlane Plane::set_mode returns at once).
        if (name != modeName) guidedRadius = 0.0
        modeName = name
        enterMode(name)
        fence.modeChanged()
    }

    private fun enterMode(name: String) {
        val flying = !body.onGround
        val alt = body.location.altitude.meters
        if (activity == Activity.Mission && Modes.behaviour(autopilot, type, name) != Behaviour.AUTO) mission.stop()
        activity = when (Modes.behaviour(autopilot, type, name) ?: Behaviour.HOLD) {
            Behaviour.MANUAL -> when {
                !flying -> Activity.Parked
                // Throttle at minimum with the motors passing it through (ArduCopter
                // mode_stabilize.cpp ModeStabilize::run: get_pilot_desired_throttle): it drops.
                multirotor -> Activity.Descending(null, MultirotorAirframe.FALL_SPEED)
                else -> Activity.Cruise(body.heading, alt)
            }
            Behaviour.STICK_CLIMB_RATE -> when {
                !flying -> Activity.Parked
                multirotor -> Activity.Descending(if (name == "ALT_HOLD") null else body.location, pilotDescentRate())
                else -> holdHere()
            }
            Behaviour.HOLD, Behaviour.GUIDED -> if (flying) holdHere(if (name == "BRAKE" && !isPx4) BRAKE_DECELERATION else null) else Activity.Parked
            Behaviour.CIRCLE -> if (!flying) {
                Activity.Parked
            } else if (multirotor) {
                val r = params["CIRCLE_RADIUS"] / 100
                val h = Math.toRadians(body.heading)
                Activity.Hold(moved(body.location, cos(h) * r, sin(h) * r, 0.0), r, params["CIRCLE_RATE"] >= 0)
            } else {
                holdHere()
            }
            Behaviour.AUTO -> {
                mission.start()
                Activity.Mission
            }
            Behaviour.RTL -> if (flying) Activity.Returning(returnPlan()) else Activity.Parked
            Behaviour.LAND -> if (flying) Activity.Landing(if (multirotor) null else body.location) else Activity.Parked
            Behaviour.TAKEOFF -> {
                val target = takeoffAltitude(null)
                when {
                    flying && alt >= target - 1 -> holdHere()
                    else -> Activity.Takeoff(target, if (isPx4) "AUTO.LOITER" else if (multirotor) null else "LOITER")
                }
            }
        }
    }

    /**
     * How fast an ArduCopter descends with the throttle stick at minimum, m/s: PILOT_SPEED_DN, or
     * PILOT_SPEED_UP when that is 0 (ArduCopter/Attitude.cpp Copter::get_pilot_speed_dn).
     */
    fun pilotDescentRate(): Double = params["PILOT_SPEED_DN"].takeIf { it > 0 }.let { it ?: params["PILOT_SPEED_UP"] } / 100

    /**
     * Whether a take-off to [target] (AMSL) is done: a multirotor within 0.3 m of it, a plane within
     * 2 m, but neither lower than 1.5 m above the ground (a plane's take-off to PX4's default 2.5 m
     * would otherwise end at 0.5 m, and the world's terrain check would end the flight).
     */
    fun takeoffReached(target: Double): Boolean =
        body.location.altitude.meters >= maxOf(target - if (multirotor) 0.3 else 2.0, minOf(target, ground + 1.5))

    /** Take-off altitude (AMSL) for a take-off with [requested] metres (null: the flavour's default). */
    fun takeoffAltitude(requested: Double?): Double = home.altitude.meters + (
        requested ?: when {
            isPx4 -> params["MIS_TAKEOFF_ALT"]
            multirotor -> 2.5
            else -> params["TKOFF_ALT"]
        }
        )

    /**
     * Holding here: a multirotor hovers where it stops, braking at [braking] m/s² (null: its own
     * acceleration limit), not where it was when told (it would overshoot and fly back); a plane
     * circles at the loiter radius. ArduCopter BRAKE stops at BRAKE_MODE_DECEL_RATE
     * (ArduCopter/mode_brake.cpp ModeBrake::init: the position controller's stopping point at that
     * deceleration); GUIDED's entry holds the waypoint controller's stopping point
     * (ArduCopter/mode_guided.cpp ModeGuided::init); PX4 Hold the braking position
     * (src/modules/navigator/loiter.cpp Loiter::on_activation, set_loiter_position from the
     * multicopter's stopping point, MPC_ACC_HOR).
     */
    fun holdHere(braking: Double? = null): Activity = if (multirotor) {
        val a = braking ?: performance().acceleration
        val speed = kotlin.math.hypot(body.velocityNorth, body.velocityEast)
        val distance = speed * speed / (2 * a)
        val stop = if (speed < 0.1) body.location else moved(body.location, body.velocityNorth / speed * distance, body.velocityEast / speed * distance, 0.0)
        Activity.Hold(stop, 0.0, braking = braking)
    } else {
        loiterRadius().let { (r, cw) -> Activity.Hold(body.location, r, cw) }
    }

    /** A return to launch with this flavour's altitude and radius. */
    fun returnPlan(): ReturnPlan {
        val alt = body.location.altitude.meters
        val (radius, cw) = loiterRadius()
        return when {
            isPx4 -> ReturnPlan(home, maxOf(home.altitude.meters + params["RTL_RETURN_ALT"], if (multirotor) alt else 0.0), multirotor, radius, cw)
            multirotor -> ReturnPlan(home, maxOf(home.altitude.meters + params["RTL_ALT"] / 100, alt), true, 0.0, true)
            else -> {
                val rtlAlt = params["ALT_HOLD_RTL"].let { if (it < 0) alt else home.altitude.meters + it / 100 }
                val r = params["RTL_RADIUS"].let { if (it == 0.0) radius to cw else kotlin.math.abs(it) to (it > 0) }
                ReturnPlan(home, rtlAlt, false, r.first, r.second)
            }
        }
    }

    /** Moves home to [location] and announces it. */
    fun setHome(location: Location) {
        home = location
        emit(SimOutput.HomeChanged)
    }

    /** Makes [seq] the mission server's current item (as MISSION_SET_CURRENT would). */
    fun setCurrent(seq: Int) {
        missionServer.onMessage(MissionMessage.SetCurrent(seq), 0)
    }

    /** The vehicle is flying (not on the ground). */
    val flying: Boolean get() = !body.onGround

    /** [location] at altitude [amsl]. */
    fun at(location: Location, amsl: Double): Location = atAltitude(location, amsl)

    companion object {
        /** A full pack lasts 20 minutes of flight. */
        const val FULL_DRAIN_SECONDS = 20 * 60.0
        /** An empty pack is full again after an hour on the ground (a charging pad or a swap). */
        const val FULL_RECHARGE_SECONDS = 60 * 60.0
        /** ArduCopter BRAKE's deceleration, m/s² (BRAKE_MODE_DECEL_RATE, 750 cm/s², ArduCopter/config.h). */
        const val BRAKE_DECELERATION = 7.5
        /** How high above the ground a vehicle flying away from a take-off or landing must stay, m. */
        const val TERRAIN_CLEARANCE = 1.0
        /** Over the ground faster than this, m/s, a vehicle counts as flying along it rather than hovering. */
        const val TERRAIN_MOVING_SPEED = 1.0
    }
}
