package pod.sim.autopilot

import pod.core.vehicle.Severity
import pod.core.units.Location
import pod.core.vehicle.Autopilot
import pod.core.vehicle.LandedState
import pod.core.vehicle.VehicleType
import pod.mavlink.mission.MissionItem
import pod.mavlink.mission.MissionMessage
import pod.mavlink.mission.MissionType
import pod.mavlink.protocol.Step
import pod.mavlink.telemetry.FlightModes
import pod.mavlink.vehicle.MissionServer
import pod.sim.PhotoEvent
import pod.sim.SimState
import pod.sim.autopilot.profile.AutopilotProfile
import pod.sim.flight.Body
import pod.sim.flight.Guidance
import pod.sim.flight.Performance
import pod.sim.flight.atAltitude
import pod.sim.flight.horizontalDistance
import pod.sim.world.SimWorld
import pod.core.units.Speed
import pod.core.units.deg
import pod.core.units.m
import kotlin.time.Duration.Companion.seconds

/**
 * The simulated autopilot: modes, arming, commands, missions, parameters and the physics, as a
 * pure state machine. [step] advances simulated time by a fixed step; commands and messages go in
 * through [commands] and [params]; what should be sent collects in [drain]. No coroutines, no
 * clocks: tests drive it by stepping time. What differs between firmwares is its [profile]'s.
 */
internal class SimAutopilot(
    val autopilot: Autopilot,
    override val type: VehicleType,
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
    override val world: SimWorld = SimWorld(home.altitude.meters),
) : FlightControl {
    /** Everything the firmware it plays does differently. */
    override val profile: AutopilotProfile = AutopilotProfile.of(autopilot, type)
    override val params = SimParameters(profile.parameters(systemId), profile.integersBytewise, profile.refusesOutOfRange)
    override val speeds = SpeedOverrides()
    val commands = Commands(this)
    val paramResponder = ParamResponder(params, profile, ::emit)
    override val mission = MissionRunner(this)
    override val camera = CameraPayload()
    override val fence: Geofence = profile.fence(this)
    private val modes = ModeEntry(this)

    /** Elevation AMSL in metres of the ground straight below the vehicle (the terrain's, or flat). */
    override val ground: Double get() = world.groundAt(body.location)

    override var time = 0.0; private set
    override var body = Body(home, heading = 0.0); private set
    override var home: Location = home; private set
    override var charge = charge; private set
    override var armed = false; private set
    override var modeName: String = profile.bootMode; private set
    override var activity: Activity = Activity.Parked; private set

    /**
     * ArduPlane GUIDED's loiter radius from a DO_REPOSITION's param3, m (0: WP_LOITER_RAD). It
     * lasts while the plane stays in GUIDED: ModeGuided::_enter sets active_radius_m to 0, and
     * ModeGuided::set_radius_and_direction is the only other writer (ArduPlane/mode_guided.cpp).
     */
    override var guidedRadius = 0.0
        private set

    override fun setGuidedRadius(radius: Double) = run { guidedRadius = radius }

    private val outbox = ArrayList<SimOutput>()
    private val contact = GroundContact(this)
    private var lastCurrent = -1
    val reached = ArrayList<Int>()
    val photos = ArrayList<PhotoEvent>()

    /**
     * Whether a ground station may clear [type]'s list now (the [missionServer]'s `clearAllowed`):
     * not a mission it is flying, where the profile says so ([AutopilotProfile.refusesClearWhileFlyingMission]).
     */
    fun allowsClearing(type: MissionType): Boolean =
        !profile.refusesClearWhileFlyingMission || type != MissionType.MISSION || !(armed && modeName == "AUTO" && mission.running)

    /**
     * True once the simulated GPS has a fix and the estimator has set its origin. ArduPilot has no
     * home before that: Copter::update_home_from_EKF (ArduCopter/commands.cpp) sets home to the
     * current location only once AP_AHRS has an origin, and GCS_MAVLINK::send_home_position sends
     * nothing while AP_AHRS::home_is_set() is false.
     */
    override val positionReady: Boolean get() = time >= readyAfter

    /**
     * True once the estimator's position is good enough for the modes that navigate (ArduCopter's
     * Copter::position_ok); before, ArduCopter refuses GUIDED, AUTO, BRAKE… with "requires position".
     */
    override val navigationReady: Boolean get() = time >= maxOf(readyAfter, navigationReadyAfter)

    /** True once the inertial sensors have settled (ArduPilot SITL: "Accels inconsistent" until then). */
    override val sensorsReady: Boolean get() = time >= sensorsReadyAfter

    /** The messages to send, oldest first; empties the queue. */
    fun drain(): List<SimOutput> = outbox.toList().also { outbox.clear() }

    override fun emit(output: SimOutput) {
        outbox += output
    }

    override fun text(severity: Severity, text: String) = emit(SimOutput.Text(severity, text))

    /** A snapshot for telemetry. */
    fun state(): SimState = SimState(
        location = body.location, home = home,
        velocityNed = Triple(Speed(body.velocityNorth), Speed(body.velocityEast), Speed(body.velocityDown)),
        heading = body.heading.deg, charge = charge, armed = armed, landedState = landedState(),
        customMode = FlightModes.customMode(autopilot, type, modeName) ?: 0, modeName = modeName,
        airspeed = Speed(body.airspeed), throttle = body.throttle, missionCurrent = missionServer.current, positionReady = positionReady,
        target = target(), groundAltitude = ground.m, time = time.seconds, crashed = crashed,
    )

    private fun target(): Location? = when (val a = activity) {
        is Activity.GoTo -> a.target
        Activity.Mission -> mission.target
        else -> null
    }

    /**
     * Hands a mission-protocol message from a ground station to the mission server at [now] (the
     * server's clock) and returns its step (replies, wake time), reacting to the list as it is
     * afterwards ([missionChanged]). MISSION_SET_CURRENT while flying the mission restarts the item
     * named where the profile says so ([AutopilotProfile.setCurrentRestartsItem]): an upload that
     * rewrote the item being flown takes effect with it.
     */
    fun onMissionMessage(message: MissionMessage, now: Long): Step<MissionMessage, Nothing> {
        val replies = missionServer.onMessage(message, now)
        missionChanged()
        if (message is MissionMessage.SetCurrent && profile.setCurrentRestartsItem && activity == Activity.Mission) mission.restart()
        return replies
    }

    override fun landedState(): LandedState = when {
        body.onGround && body.airspeed < 0.5 -> LandedState.ON_GROUND
        body.onGround -> if (activity is Activity.Takeoff) LandedState.TAKEOFF else LandedState.LANDING
        activity is Activity.Takeoff -> LandedState.TAKEOFF
        landing -> LandedState.LANDING
        else -> LandedState.IN_AIR
    }

    /** Landing now: a LAND, a return descending over home, or a mission's landing item. */
    val landing: Boolean get() = activity is Activity.Landing || (activity as? Activity.Returning)?.plan?.landing == true || mission.landing

    /** Flight performance from the parameters and any DO_CHANGE_SPEED overrides. */
    override fun performance(): Performance = profile.performance(params, speeds)

    /** A plane's loiter radius (positive) and direction. */
    override fun loiterRadius(): Pair<Double, Boolean> = profile.loiterCircle(params)

    /** Acceptance radius for waypoints: [requested] when positive, else the profile's parameter. */
    override fun acceptanceRadius(requested: Float): Double {
        if (requested > 0) return requested.toDouble()
        return profile.defaultAcceptanceRadius(params)
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
        body = profile.airframe.step(body, guidance, performance().let { p -> if (braking == null) p else p.copy(acceleration = maxOf(p.acceleration, braking)) }, ground, armed, dt)
        contact.checkTerrainClearance(guidance)
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
            // Only where the firmware announces it (PX4's mission manager); ArduPilot streams
            // MISSION_CURRENT when asked and answers MISSION_SET_CURRENT with one.
            if (profile.announcesMissionCurrent) emit(SimOutput.MissionCurrent(lastCurrent))
        }
    }

    private fun guidance(): Guidance = when (val a = activity) {
        Activity.Parked -> Guidance.Idle
        is Activity.Takeoff -> if (armed) Guidance.Climb(a.altitude) else Guidance.Idle
        is Activity.Hold -> Guidance.Loiter(a.center, a.radius, a.clockwise)
        is Activity.GoTo -> {
            val (radius, clockwise) = if (a.radius > 0) a.radius to a.clockwise else loiterRadius()
            when {
                // Airframe, not firmware: a multirotor flies straight there and hovers.
                profile.rotorcraft -> Guidance.GoTo(a.target, a.speed)
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

    /** Why the simulator ended the flight ("flew into terrain"), or null (see [GroundContact]). */
    val crashed: String? get() = contact.crashed

    private fun afterStep() {
        when (val a = activity) {
            is Activity.Takeoff -> if (takeoffReached(a.altitude)) {
                // Take-off done, the mode takes over: GUIDED holds, LOITER with no stick input sinks.
                if (a.then != null) setMode(a.then) else activity = modes.activityFor(modeName)
            }
            // Airframe, not firmware: a hovering multirotor that arrived holds there.
            is Activity.GoTo -> if (profile.rotorcraft && horizontalDistance(body.location, a.target) < 0.5 &&
                kotlin.math.abs(body.location.altitude.meters - a.target.altitude.meters) < 0.5
            ) {
                activity = Activity.Hold(a.target, 0.0)
            }
            else -> Unit
        }
        if (body.onGround && body.airspeed < 0.1 && activity != Activity.Parked && activity !is Activity.Takeoff && landing) {
            contact.landedByLanding = true
            if (activity == Activity.Mission) mission.touchedDown() else activity = Activity.Parked
        }
        if (activity == Activity.Mission && mission.finishedOnGround) activity = Activity.Parked
        // Touched down with the throttle at minimum: landed, and disarmed after DISARM_DELAY.
        if (activity is Activity.Descending && body.onGround && body.airspeed < 0.1) activity = Activity.Parked
        contact.autoDisarm()
    }

    /**
     * Reacts to the mission list as it is now; called every step and right after each mission
     * message, since ArduPlane notices within one loop: AUTO with no mission to run switches to
     * the profile's [AutopilotProfile.modeWhenMissionGone].
     */
    fun missionChanged() {
        if (mission.hasMission()) return
        val next = profile.modeWhenMissionGone(modeName) ?: return
        setMode(next)
        text(Severity.INFO, "Aircraft in auto without a running mission")
    }

    /** Arms (checks are the caller's business). */
    override fun arm() {
        armed = true
        contact.armed()
        if (activity == Activity.Parked && profile.behaviour(modeName) == Behaviour.TAKEOFF) activity = modes.activityFor(modeName)
    }

    /** Disarms; in the air the vehicle falls (a multirotor) or glides down (a plane). */
    override fun disarm() {
        armed = false
        contact.disarmed()
        if (body.onGround) activity = Activity.Parked
    }

    /** Switches to mode [name] and starts what it does (the caller checked that it may). */
    override fun setMode(name: String) {
        // Selecting the mode it is in enters nothing (ArduPlane Plane::set_mode returns at once).
        if (name != modeName) guidedRadius = 0.0
        modeName = name
        if (activity == Activity.Mission && profile.behaviour(name) != Behaviour.AUTO) mission.stop()
        activity = modes.activityFor(name)
        fence.modeChanged()
    }

    /** From now on the vehicle does [activity] (a command's or the fence's doing), in the mode it is in. */
    override fun fly(activity: Activity) = run { this.activity = activity }

    /**
     * Whether a take-off to [target] (AMSL) is done: a multirotor within 0.3 m of it, a plane within
     * 2 m, but neither lower than 1.5 m above the ground (a plane's take-off to PX4's default 2.5 m
     * would otherwise end at 0.5 m, and the world's terrain check would end the flight). The
     * tolerance is the airframe's, not a firmware's.
     */
    override fun takeoffReached(target: Double): Boolean =
        body.location.altitude.meters >= maxOf(target - if (profile.rotorcraft) 0.3 else 2.0, minOf(target, ground + 1.5))

    /** Take-off altitude (AMSL) for a take-off with [requested] metres (null: the profile's default). */
    override fun takeoffAltitude(requested: Double?): Double = home.altitude.meters + (requested ?: profile.defaultTakeoffHeight(params))

    /** Holding here (see [ModeEntry.holdHere]). */
    override fun holdHere(braking: Double?): Activity = modes.holdHere(braking)

    /** A return to launch with the profile's altitude and radius, flown as the airframe flies (climb first and land, or circle). */
    override fun returnPlan(): ReturnPlan {
        val (alt, radius, clockwise) = profile.returnAltitude(params, home.altitude.meters, body.location.altitude.meters)
        return ReturnPlan(home, alt, profile.rotorcraft, radius, clockwise)
    }

    /** Moves home to [location] and announces it. */
    override fun setHome(location: Location) {
        home = location
        emit(SimOutput.HomeChanged)
    }

    /** Records mission item [seq] as reached and says so (MISSION_ITEM_REACHED). */
    override fun itemReached(seq: Int) {
        reached += seq
        emit(SimOutput.ItemReached(seq))
    }

    /** Makes [seq] the mission server's current item (as MISSION_SET_CURRENT would). */
    override fun setCurrent(seq: Int) {
        missionServer.onMessage(MissionMessage.SetCurrent(seq), 0)
    }

    /** The MISSION list as the server holds it. */
    override val missionItems: List<MissionItem> get() = missionServer.list(MissionType.MISSION)

    /** The FENCE list as the server holds it. */
    override val fenceItems: List<MissionItem> get() = missionServer.list(MissionType.FENCE)

    /** The mission server's current item. */
    override val missionCurrent: Int get() = missionServer.current

    /** The vehicle is flying (not on the ground). */
    override val flying: Boolean get() = !body.onGround

    /** [location] at altitude [amsl]. */
    override fun at(location: Location, amsl: Double): Location = atAltitude(location, amsl)

    companion object {
        /** A full pack lasts 20 minutes of flight. */
        const val FULL_DRAIN_SECONDS = 20 * 60.0
        /** An empty pack is full again after an hour on the ground (a charging pad or a swap). */
        const val FULL_RECHARGE_SECONDS = 60 * 60.0
    }
}
