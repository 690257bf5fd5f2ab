package pod.mavlink.action

import pod.mavlink.MavlinkVehicle
import pod.mavlink.command.MavCommandParams.ARM_FORCE_MAGIC
import pod.mavlink.command.MavCommands.COMPONENT_ARM_DISARM
import pod.mavlink.command.VehicleCommand

/**
 * Arming and disarming ([VehicleActions.arm], [VehicleActions.disarm]), each confirmed by the
 * heartbeat's armed flag; an arm refused while the vehicle initialises is waited out ([Readiness]).
 */
internal class Arming(private val vehicle: MavlinkVehicle, private val readiness: Readiness, private val waits: StateWaits) {
    /** Arms ([force] skips the pre-arm checks) and waits until telemetry shows it armed. */
    suspend fun arm(force: Boolean) {
        readiness.retry("arm", { ArmReadiness.waitFor(it.statusTexts, readiness.initialising()) }) {
            vehicle.commands.send(armDisarm(arm = true, force))
        }
        waits.confirm("arm", "armed", vehicle.telemetry.armed) { it }
    }

    /** Disarms ([force] even in flight) and waits until telemetry shows it disarmed. */
    suspend fun disarm(force: Boolean) {
        vehicle.commands.send(armDisarm(arm = false, force))
        waits.confirm("disarm", "disarmed", vehicle.telemetry.armed) { !it }
    }

    private fun armDisarm(arm: Boolean, force: Boolean) =
        VehicleCommand(COMPONENT_ARM_DISARM, param1 = if (arm) 1f else 0f, param2 = if (force) ARM_FORCE_MAGIC.toFloat() else 0f)
}
