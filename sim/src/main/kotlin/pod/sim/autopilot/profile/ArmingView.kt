package pod.sim.autopilot.profile

import pod.sim.autopilot.SimParameters

/** What the arming checks read of a vehicle: nothing they could change. */
internal interface ArmingView {
    /** The GPS has a fix and the estimator an origin (home exists). */
    val positionReady: Boolean

    /** The inertial sensors have settled. */
    val sensorsReady: Boolean

    /** Battery charge, 0..1. */
    val charge: Double

    /** The parameters as they are. */
    val params: SimParameters

    /** The current mode's name. */
    val modeName: String

    /** A PREFLIGHT_CALIBRATION is running. */
    val calibrating: Boolean

    /** Why the fence refuses arming, or null. */
    val fenceArmingProblem: String?

    /** The mission holds a DO_LAND_START. */
    val hasLandStart: Boolean
}
