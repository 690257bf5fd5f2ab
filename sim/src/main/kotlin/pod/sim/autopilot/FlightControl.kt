package pod.sim.autopilot

import pod.core.units.Location
import pod.core.vehicle.LandedState
import pod.core.vehicle.Severity
import pod.core.vehicle.VehicleType
import pod.mavlink.mission.MissionItem
import pod.sim.autopilot.profile.AutopilotProfile
import pod.sim.flight.Body
import pod.sim.flight.Performance
import pod.sim.world.SimWorld

/**
 * What the autopilot's collaborators (commands, the mission runner, the fence, landings) read of
 * the vehicle: its state and what follows from its parameters, nothing they could change.
 */
internal interface FlightView {
    /** What the firmware it plays does differently. */
    val profile: AutopilotProfile

    /** The airframe it announces (mode numbers follow it). */
    val type: VehicleType

    /** Its parameters. */
    val params: SimParameters

    /** The ground and objects around it. */
    val world: SimWorld

    /** Simulated seconds since boot. */
    val time: Double

    /** Its kinematic state. */
    val body: Body

    /** Home. */
    val home: Location

    /** Battery charge, 0..1. */
    val charge: Double

    /** Motors armed. */
    val armed: Boolean

    /** The current mode's name. */
    val modeName: String

    /** What it is doing. */
    val activity: Activity

    /** Elevation AMSL of the ground below it, m. */
    val ground: Double

    /** Not on the ground. */
    val flying: Boolean

    /** The GPS has a fix and home is set. */
    val positionReady: Boolean

    /** The estimator's position is good enough to navigate. */
    val navigationReady: Boolean

    /** The inertial sensors have settled. */
    val sensorsReady: Boolean

    /** The MISSION list it holds. */
    val missionItems: List<MissionItem>

    /** The FENCE list it holds. */
    val fenceItems: List<MissionItem>

    /** The mission's current item. */
    val missionCurrent: Int

    /** ArduPlane GUIDED's loiter radius from a DO_REPOSITION, m (0: the parameter's). */
    val guidedRadius: Double

    /** Speeds, rates and radii it flies with now. */
    fun performance(): Performance

    /** A plane's loiter radius (positive) and direction. */
    fun loiterRadius(): Pair<Double, Boolean>

    /** Acceptance radius for waypoints: [requested] when positive, else the profile's parameter. */
    fun acceptanceRadius(requested: Float): Double

    /** Whether a take-off to [target] (AMSL) is done. */
    fun takeoffReached(target: Double): Boolean

    /** Take-off altitude (AMSL) for a take-off with [requested] metres (null: the profile's default). */
    fun takeoffAltitude(requested: Double?): Double

    /** On the ground, taking off, in the air or landing. */
    fun landedState(): LandedState

    /** [location] at altitude [amsl]. */
    fun at(location: Location, amsl: Double): Location
}

/** What commands, the mission runner and the fence may change of the vehicle, beside what they read. */
internal interface FlightControl : FlightView {
    /** DO_CHANGE_SPEED's overrides. */
    val speeds: SpeedOverrides


    /** The mission it flies in AUTO. */
    val mission: MissionRunner

    /** Its camera. */
    val camera: CameraPayload

    /** Its geofence. */
    val fence: Geofence

    /** Sets GUIDED's loiter radius to [radius] m until the vehicle leaves the mode. */
    fun setGuidedRadius(radius: Double)

    /** Queues [output] to be sent. */
    fun emit(output: SimOutput)

    /** Queues a STATUSTEXT. */
    fun text(severity: Severity, text: String)

    /** Arms (checks are the caller's business). */
    fun arm()

    /** Disarms. */
    fun disarm()

    /** Switches to mode [name] and starts what it does (the caller checked that it may). */
    fun setMode(name: String)

    /** From now on the vehicle does [activity], in the mode it is in. */
    fun fly(activity: Activity)

    /** Moves home to [location] and announces it. */
    fun setHome(location: Location)

    /** Records mission item [seq] as reached and says so. */
    fun itemReached(seq: Int)

    /** Makes [seq] the mission's current item. */
    fun setCurrent(seq: Int)

    /** Holding here, stopping at [braking] m/s² (null: the airframe's own limit). */
    fun holdHere(braking: Double? = null): Activity

    /** A return to launch with the profile's altitude and radius. */
    fun returnPlan(): ReturnPlan
}
