package pod.mavlink.plan

import kotlinx.coroutines.withTimeoutOrNull
import pod.core.PodException
import pod.core.vehicle.Autopilot
import pod.mavlink.MavlinkVehicle
import kotlin.time.Duration.Companion.seconds

/**
 * The default speeds a .plan file records (`cruiseSpeed` for fixed wings, `hoverSpeed` for
 * multirotors, m/s), read from the vehicle's own parameters: WPNAV_SPEED (cm/s) on ArduCopter,
 * AIRSPEED_CRUISE on ArduPlane (4.5 and later), MPC_XY_CRUISE and FW_AIRSPD_TRIM on PX4.
 */
public object PlanSpeeds {
    /** [plan] with the speed [vehicle] flies by default; a speed it does not tell (no such parameter) stays as it was. */
    public suspend fun from(vehicle: MavlinkVehicle, plan: QgcPlan): QgcPlan {
        val identity = vehicle.identity.value
        val px4 = identity.autopilot == Autopilot.PX4
        return if (identity.type.isMultirotor) {
            plan.copy(hoverSpeed = (if (px4) read(vehicle, "MPC_XY_CRUISE") else read(vehicle, "WPNAV_SPEED")?.div(100)) ?: plan.hoverSpeed)
        } else {
            plan.copy(cruiseSpeed = read(vehicle, if (px4) "FW_AIRSPD_TRIM" else "AIRSPEED_CRUISE") ?: plan.cruiseSpeed)
        }
    }

    // A parameter the firmware does not have is never answered: a few seconds are enough to tell.
    private suspend fun read(vehicle: MavlinkVehicle, name: String): Double? = withTimeoutOrNull(3.seconds) {
        try {
            vehicle.params.read(name).value.takeIf { it.isFinite() && it > 0 }
        } catch (e: PodException) {
            null
        }
    }
}
