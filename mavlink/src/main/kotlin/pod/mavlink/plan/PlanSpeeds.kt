package pod.mavlink.plan

import kotlinx.coroutines.withTimeoutOrNull
import pod.core.PodException
import pod.mavlink.firmware.Firmware
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
        val firmware = Firmware.of(identity)
        return if (identity.type.isMultirotor) {
            plan.copy(hoverSpeed = read(vehicle, firmware.hoverSpeedParam)?.div(firmware.hoverSpeedPerMetre) ?: plan.hoverSpeed)
        } else {
            plan.copy(cruiseSpeed = read(vehicle, firmware.cruiseSpeedParam) ?: plan.cruiseSpeed)
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
