package pod.sim.autopilot.profile

import pod.sim.autopilot.ParamDef
import pod.sim.autopilot.ParamTables
import pod.sim.autopilot.SimParameters
import pod.sim.autopilot.SpeedOverrides
import pod.sim.flight.FixedWingAirframe
import pod.sim.flight.Performance

/** PX4 on a multicopter (the mc_* modules and the multicopter flight tasks). */
internal data object Px4MulticopterProfile : Px4Profile() {
    override val rotorcraft: Boolean get() = true

    override fun performance(params: SimParameters, overrides: SpeedOverrides): Performance = Performance(
        cruise = overrides.cruise ?: params["MPC_XY_CRUISE"], climb = overrides.climb ?: params["MPC_Z_VEL_MAX_UP"],
        descent = overrides.descent ?: params["MPC_Z_VEL_MAX_DN"], landSpeed = params["MPC_LAND_SPEED"], acceleration = params["MPC_ACC_HOR"],
    )

    /** NAV_ACC_RAD. */
    override fun defaultAcceptanceRadius(params: SimParameters): Double = params["NAV_ACC_RAD"]

    override fun parameters(systemId: Int): List<ParamDef> = ParamTables.px4Multicopter(systemId)
}

/** PX4 on a fixed wing (fw_pos_control and TECS). */
internal data object Px4FixedWingProfile : Px4Profile() {
    override val rotorcraft: Boolean get() = false

    override fun performance(params: SimParameters, overrides: SpeedOverrides): Performance = Performance(
        cruise = overrides.cruise ?: params["FW_AIRSPD_TRIM"], climb = overrides.climb ?: params["FW_T_CLMB_MAX"],
        descent = overrides.descent ?: params["FW_T_SINK_MAX"], minAirspeed = params["FW_AIRSPD_MIN"], maxAirspeed = params["FW_AIRSPD_MAX"],
        bankLimit = params["FW_R_LIM"], loiterRadius = params["NAV_LOITER_RAD"],
    )

    /** NAV_ACC_RAD, but no tighter than the plane can turn at trim airspeed and FW_R_LIM. */
    override fun defaultAcceptanceRadius(params: SimParameters): Double =
        maxOf(params["NAV_ACC_RAD"], FixedWingAirframe.turnRadius(params["FW_AIRSPD_TRIM"], params["FW_R_LIM"]))

    override fun parameters(systemId: Int): List<ParamDef> = ParamTables.px4FixedWing(systemId)
}
